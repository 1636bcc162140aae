package org.triad.dsl;

import org.eclipse.emf.ecore.EPackage;
import org.triad.dsl.triad.TriadPackage;

import com.google.inject.Injector;

/**
 * Initialization support for running Xtext languages without Equinox extension registry. Every
 * Triad language's setup runs this one first, so the hand-written metamodel is registered once
 * for all of them (Xtext does not register an imported EPackage itself).
 */
public class TriadCommonStandaloneSetup extends TriadCommonStandaloneSetupGenerated {

	public static void doSetup() {
		new TriadCommonStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	@Override
	public Injector createInjectorAndDoEMFRegistration() {
		EPackage.Registry.INSTANCE.putIfAbsent(TriadPackage.eNS_URI, TriadPackage.eINSTANCE);
		return super.createInjectorAndDoEMFRegistration();
	}
}
