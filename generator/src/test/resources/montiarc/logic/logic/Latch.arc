package logic;

/** An SR latch of two Nor gates whose feedback goes through Hold delays. */
component Latch {
  port <<sync>> in boolean s;
  port <<sync>> in boolean r;
  port <<sync>> out boolean q0, q1;

  Nor norS, norR;

  s -> norS.a;
  r -> norR.a;
  norS.q -> q0;
  norR.q -> q1;

  Hold<Boolean> holdS(false), holdR(false);

  norS.q -> holdS.i;
  norR.q -> holdR.i;
  holdS.o -> norR.b;
  holdR.o -> norS.b;
}
