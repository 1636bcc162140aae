package logic;

component Nor {
  port <<sync>> in boolean a,
       <<sync>> in boolean b;
  port <<sync>> out boolean q;

  compute {
    q = !(a || b);
  }
}
