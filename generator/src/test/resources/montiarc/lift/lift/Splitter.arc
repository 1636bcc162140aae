package lift;

/** The floor number the lift cleared as one flag per floor. */
component Splitter {
  port <<sync>> in Integer i,
       <<sync>> out Boolean o1, o2, o3;

  compute {
    boolean none = i == null;
    if (none) {
      o1 = false;
      o2 = false;
      o3 = false;
    } else {
      switch (i) {
        case 1: {
          o1 = true;
          o2 = false;
          o3 = false;
          break;
        }
        case 2: {
          o1 = false;
          o2 = true;
          o3 = false;
          break;
        }
        case 3: {
          o1 = false;
          o2 = false;
          o3 = true;
          break;
        }
        default: {
          o1 = false;
          o2 = false;
          o3 = false;
          break;
        }
      }
    }
  }
}
