package refarc;

import org.triad.refarc.*;

/* Extension: behaviour in org.triad.refarc.RemoteOperator (TOP pattern: generated RemoteOperatorTOP). */
component RemoteOperator {
  port in Status status;
}
