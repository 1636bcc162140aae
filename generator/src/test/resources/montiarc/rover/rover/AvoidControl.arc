package rover;

import rover.Signals.*;

/** Drives ahead; at a near obstacle reverses until the alarm rings, then rotates until it rings again. */
component AvoidControl {
  port
     in Integer range,
     in Alarm alarm,
     out AlarmCmd alarmCmd,
     out WheelCmd leftWheel,
     out WheelCmd rightWheel,
     out String status;

  <<sync>> automaton {
    initial {
      leftWheel = WheelCmd.HALT;
      rightWheel = WheelCmd.HALT;
      status = "idle";
    } state Idle;

    state Cruising;
    state Reversing;
    state Rotating;

    Idle -> Cruising / {
      leftWheel = WheelCmd.AHEAD;
      rightWheel = WheelCmd.AHEAD;
      status = "cruising";
    };

    Cruising -> Reversing [range < 10] / {
      leftWheel = WheelCmd.REVERSE;
      rightWheel = WheelCmd.REVERSE;
      alarmCmd = AlarmCmd.SHORT;
      status = "reversing";
    };

    Reversing -> Rotating [alarm == Alarm.RING] / {
      leftWheel = WheelCmd.AHEAD;
      rightWheel = WheelCmd.REVERSE;
      alarmCmd = AlarmCmd.LONG;
      status = "rotating";
    };

    Rotating -> Cruising [alarm == Alarm.RING] / {
      leftWheel = WheelCmd.AHEAD;
      rightWheel = WheelCmd.AHEAD;
      status = "cruising";
    };
  }
}
