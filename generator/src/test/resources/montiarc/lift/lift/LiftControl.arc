package lift;

import lift.Commands.Motion;
import lift.Commands.DoorCmd;

/** Homes the cabin to floor 1, then serves requests: lowest floor first, doors open on arrival. */
component LiftControl {
  port in Boolean req1, req2, req3,
       in Boolean at1, at2, at3,
       out Motion motion,
       out DoorCmd door,
       <<delayed>> out Integer clear;

  int target = 0;
  int current = 0;
  int trips = 0;

  <<sync>> automaton {
    initial { clear = 0; } state Start {
      initial state Settle;
      state Home;

      Settle -> Settle [!at1] / {
        motion = Motion.DOWN;
      };
      Settle -> Home [at1] / {
        current = 1;
        motion = Motion.STOP;
      };
      Home -> Idle;
    };

    state Idle {
      entry / {
        door = DoorCmd.CLOSE;
      }
      initial state Scan;
      state Chosen;

      Scan -> Chosen [req1] / {
        target = 1;
      };
      Scan -> Chosen [!req1 && req2] / {
        target = 2;
      };
      Scan -> Chosen [!req1 && !req2 && req3] / {
        target = 3;
      };
    };

    state Moving {
      entry / {
        trips = trips + 1;
      }
      exit / {
        motion = Motion.STOP;
      }
    };

    state Open;

    Chosen -> Open [target == current] / {
      door = DoorCmd.OPEN;
      clear = target;
    };
    Chosen -> Moving [target > current] / {
      motion = Motion.UP;
    };
    Chosen -> Moving [target < current] / {
      motion = Motion.DOWN;
    };
    Moving -> Open [target == 1 && at1 || target == 2 && at2 || target == 3 && at3] / {
      current = target;
      door = DoorCmd.OPEN;
      clear = target;
    };
    Open -> Idle;
  }
}
