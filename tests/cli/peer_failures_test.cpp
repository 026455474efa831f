// A peer that ends the process it runs in is the case's finding, never the end of the command
// that asks it (src/tool/cases.cpp: every command asks the parties in a child): ODE's dCollide
// replaced, through LD_PRELOAD, by one that exits with status 7, then a stored tri_tri case (ODE
// answers tri_tri) replayed and triaged.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "program_run.h"
#include "temp_folder.h"

namespace cc::test {
namespace {

const std::string kCase = std::string(CROSSCHECK_SOURCE_DIR) + "/corpora/tri_tri/0107e6984e6847ac.json";

// crosscheck with ODE's dCollide exiting (ASan, where it is built in, must let a library load first).
Outcome with_a_peer_that_exits(const std::vector<std::string>& arguments, const TempFolder& folder) {
  std::vector<std::string> argv = {"env", "LD_PRELOAD=" CROSSCHECK_PEER_THAT_EXITS, "ASAN_OPTIONS=verify_asan_link_order=0",
                                   CROSSCHECK_BINARY};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return run(argv, folder.path(), folder.path());
}

TEST(PeerFailures, ReplayReportsAPeerThatExitsAsTheCasesChangeAndGoesOn) {
  const TempFolder folder("crosscheck_peer_exits_replay");
  const Outcome r = with_a_peer_that_exits({"replay", kCase, kCase}, folder);
  EXPECT_EQ(r.status, 1) << r.out << r.err;  // changed, not the peer's status 7
  EXPECT_NE(r.out.find("ode.dCollide(dTriMesh,dTriMesh) changed its behaviour: recorded {\"hit\":false}, now failed"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("2 cases replayed: 0 unchanged, 2 changed"), std::string::npos) << r.out;
}

TEST(PeerFailures, TriageShowsAPeerThatExitsAsItsFailure) {
  const TempFolder folder("crosscheck_peer_exits_triage");
  const Outcome r = with_a_peer_that_exits({"triage", kCase}, folder);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("ode.dCollide(dTriMesh,dTriMesh)  failed: exited with status 7 in the second opinions"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("library    miss   [right]"), std::string::npos) << r.out;  // the library still answered
}

}  // namespace
}  // namespace cc::test
