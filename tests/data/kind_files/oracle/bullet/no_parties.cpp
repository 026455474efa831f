// A peer's kinds without parties, in the small tree of cli.kind_files tests: this line is
// broadphase's unit in oracle/bullet.
CC_NO_PARTIES(bullet_parties, broadphase, Broadphase, "a reason")
