package logic;

/** A generic component with a bound, extended with arguments below. */
component Clamp<T extends Number>(int limit) {
  port <<sync>> in T x;
  port <<sync>> out Integer y;

  compute {
    int v = x.intValue();
    if (v > limit) {
      y = limit;
    } else {
      y = v;
    }
  }
}
