package org.triad.dsl.conversion;

import org.eclipse.xtext.common.services.DefaultTerminalConverters;
import org.eclipse.xtext.conversion.IValueConverter;
import org.eclipse.xtext.conversion.ValueConverter;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;

/**
 * Opaque guards, actions and arguments of .arc models keep their tokens with single spaces where the
 * text had whitespace or comments; the default datatype conversion would glue tokens together
 * ({@code new Foo()} would become {@code newFoo()}).
 */
public class ArcValueConverters extends DefaultTerminalConverters {
	private static final IValueConverter<String> TOKEN_TEXT = new IValueConverter<>() {
		@Override
		public String toValue(String string, INode node) {
			return node == null ? string : NodeModelUtils.getTokenText(node).trim();
		}

		@Override
		public String toString(String value) {
			return value;
		}
	};

	@ValueConverter(rule = "Opaque")
	public IValueConverter<String> Opaque() {
		return TOKEN_TEXT;
	}

	@ValueConverter(rule = "Argument")
	public IValueConverter<String> Argument() {
		return TOKEN_TEXT;
	}
}
