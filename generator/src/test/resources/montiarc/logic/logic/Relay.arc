package logic;

/** An event automaton (no stereotype) with a delayed port: each message goes out one slice later (MontiArc's Delay). */
component Relay<T> {
  port in T i;
  port <<delayed>> out T o;

  automaton {
    initial state S;
    S -> S i / {
      o = i;
    };
  }
}
