package refarc;

import org.triad.refarc.*;

/* Behaviour is hand-written in org.triad.refarc.StateProvider (TOP pattern: generated StateProviderTOP).
   One query/answer pair per client, because an in port has one sender. */
component StateProvider(StateSource stateSource) {
  port in StateRequest plannerQuery;
  port out StateSnapshot plannerState;
  port in StateRequest executorQuery;
  port out StateSnapshot executorState;
}
