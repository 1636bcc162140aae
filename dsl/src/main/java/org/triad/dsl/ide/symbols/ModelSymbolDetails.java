package org.triad.dsl.ide.symbols;

import org.triad.dsl.semantics.ArcModels;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.ide.server.symbol.DocumentSymbolMapper.DocumentSymbolDetailsProvider;
import org.triad.dsl.arc.ArcPort;
import org.triad.dsl.arc.ComponentType;
import org.triad.dsl.arc.PortDeclaration;
import org.triad.dsl.arc.Subcomponent;
import org.triad.dsl.ide.hover.ModelSignatures;
import org.triad.dsl.triad.Action;
import org.triad.dsl.triad.Actor;
import org.triad.dsl.triad.Attribute;
import org.triad.dsl.triad.DomainClass;
import org.triad.dsl.triad.Goal;
import org.triad.dsl.triad.ObjectDeclaration;
import org.triad.dsl.triad.Parameter;
import org.triad.dsl.triad.Property;
import org.triad.dsl.triad.SituationObject;
import org.triad.dsl.triad.Task;

import com.google.inject.Singleton;

/** The one-line detail beside a symbol: parameters and types, as the model writes them. */
@Singleton
public class ModelSymbolDetails extends DocumentSymbolDetailsProvider {
	@Override
	public String getDetails(EObject o) {
		if (o instanceof Property p) {
			return "(" + ModelSignatures.parameters(p.getParameters()) + "): " + ModelSignatures.type(p.getType());
		}
		if (o instanceof Action || o instanceof Goal || o instanceof Task) {
			return "(" + ModelSignatures.parameters(((org.triad.dsl.triad.Parameterized) o).getParameters()) + ")";
		}
		if (o instanceof Parameter p) {
			return ModelSignatures.type(p.getType());
		}
		if (o instanceof Attribute a) {
			return ModelSignatures.type(a.getType());
		}
		if (o instanceof Actor a) {
			return a.getKind().getLiteral();
		}
		if (o instanceof DomainClass c) {
			return c.getSuperType() != null && !c.getSuperType().eIsProxy() ? "extends " + c.getSuperType().getName() : "";
		}
		if (o instanceof SituationObject s && s.eContainer() instanceof ObjectDeclaration d && d.getType() != null && !d.getType().eIsProxy()) {
			return d.getType().getName();
		}
		if (o instanceof ArcPort p && p.eContainer() instanceof PortDeclaration d) {
			return d.getDirection().getLiteral() + " " + d.getType();
		}
		if (o instanceof Subcomponent s && ArcModels.type(s) != null && !ArcModels.type(s).eIsProxy()) {
			return ArcModels.type(s).getName();
		}
		if (o instanceof ComponentType c) {
			return "component";
		}
		return "";
	}
}
