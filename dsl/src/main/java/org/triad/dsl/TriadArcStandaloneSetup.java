package org.triad.dsl;

import org.eclipse.emf.ecore.EPackage;
import org.triad.dsl.arc.ArcPackage;

import com.google.inject.Injector;

/**
 * Initialization support for running the architecture language without Equinox extension registry;
 * registers the hand-written Arc metamodel, which Xtext does not register for an imported EPackage.
 */
public class TriadArcStandaloneSetup extends TriadArcStandaloneSetupGenerated {

	public static void doSetup() {
		new TriadArcStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	@Override
	public Injector createInjectorAndDoEMFRegistration() {
		EPackage.Registry.INSTANCE.putIfAbsent(ArcPackage.eNS_URI, ArcPackage.eINSTANCE);
		return super.createInjectorAndDoEMFRegistration();
	}
}
