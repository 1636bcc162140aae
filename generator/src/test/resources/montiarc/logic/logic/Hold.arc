package logic;

/** Delays by one slice and sends iv in the first (MontiArc's TSDelay). */
component Hold<T>(T iv) {
  port <<sync>> in T i;
  port <<sync, delayed>> out T o;

  init {
    o = iv;
  }

  compute {
    o = i;
  }
}
