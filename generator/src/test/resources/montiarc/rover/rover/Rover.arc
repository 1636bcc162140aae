package rover;

component Rover {
  port <<sync>> in Integer range,
       <<sync>> out rover.Signals.WheelCmd left, right,
       <<sync>> out String status;

  AvoidControl control;
  AlarmClock clock(2, 3);

  range -> control.range;
  control.leftWheel -> left;
  control.rightWheel -> right;
  control.status -> status;
  control.alarmCmd -> clock.cmd;
  clock.alarm -> control.alarm;
}
