package lift;

/** Lights when pressed and stays lit until the lift clears its floor. */
component FloorButton {
  port in Boolean pressed,
       in Boolean clear,
       out Boolean light;

  <<sync>> automaton {
    initial state Off;
    state On;

    Off -> On [pressed && !clear] / {
      light = true;
    };
    Off -> Off [!pressed || clear] / {
      light = false;
    };
    On -> Off [clear] / {
      light = false;
    };
    On -> On [!clear] / {
      light = true;
    };
  }
}
