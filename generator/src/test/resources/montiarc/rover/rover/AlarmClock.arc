package rover;

import rover.Signals.AlarmCmd;
import rover.Signals.Alarm;

/** Rings shortTicks or longTicks slices after a command; its alarm is delayed, which breaks the loop with the controller. */
component AlarmClock(int shortTicks, int longTicks) {
  port
    <<sync>> in rover.Signals.AlarmCmd cmd,
    <<sync, delayed>> out rover.Signals.Alarm alarm;

  int remaining = 0;

  <<sync>> automaton {
    initial state Quiet;
    state Counting;

    Quiet -> Counting [cmd == AlarmCmd.SHORT] / {
      remaining = shortTicks;
    };
    Quiet -> Counting [cmd == AlarmCmd.LONG] / {
      remaining = longTicks;
    };
    Counting -> Counting [remaining > 1] / {
      remaining = remaining - 1;
      alarm = Alarm.QUIET;
    };
    Counting -> Quiet [remaining <= 1] / {
      alarm = Alarm.RING;
    };
  }
}
