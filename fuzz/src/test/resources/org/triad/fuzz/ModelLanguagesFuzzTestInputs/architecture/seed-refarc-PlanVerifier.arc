package refarc;

import org.triad.refarc.*;

/* Extension: behaviour in org.triad.refarc.PlanVerifier (TOP pattern: generated PlanVerifierTOP). */
component PlanVerifier(PlanCheck check) {
  port in PlanResult proposed;
  port out PlanResult verified;
}
