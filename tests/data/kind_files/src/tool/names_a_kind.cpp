// A tree for `crosscheck kind-files` (tests/CMakeLists.txt): this tool file names a kind outside
// its units, which --check must report.
const auto kind = harness::QueryKind::tri_obb;
