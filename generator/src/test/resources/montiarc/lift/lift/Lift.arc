package lift;

component Lift {
  port <<sync>> in Boolean btn1, btn2, btn3,
       <<sync>> in Boolean at1, at2, at3,
       <<sync>> out Boolean light1, light2, light3,
       <<sync>> out lift.Commands.Motion motion,
       <<sync>> out lift.Commands.DoorCmd door;

  FloorButton b1, b2, b3;
  Splitter splitter;
  LiftControl ctrl;

  btn1 -> b1.pressed;
  btn2 -> b2.pressed;
  btn3 -> b3.pressed;
  b1.light -> light1, ctrl.req1;
  b2.light -> light2, ctrl.req2;
  b3.light -> light3, ctrl.req3;

  ctrl.clear -> splitter.i;
  splitter.o1 -> b1.clear;
  splitter.o2 -> b2.clear;
  splitter.o3 -> b3.clear;

  at1 -> ctrl.at1;
  at2 -> ctrl.at2;
  at3 -> ctrl.at3;
  ctrl.motion -> motion;
  ctrl.door -> door;
}
