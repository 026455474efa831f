// ODE's dCollide replaced by one that ends the process it runs in, for the command-line tests
// (loaded with LD_PRELOAD ahead of ODE): a peer that exits in a case must be that case's finding,
// never the end of the command asking it.
#include <unistd.h>

extern "C" int dCollide(void*, void*, int, void*, int) { _exit(7); }
