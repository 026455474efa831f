// The audit of the exact reference by CGAL: one case answered by both and compared. CGAL
// answers every kind whose input's fields, in their order, a cgal_answer of cgal_audit.h takes
// (two shapes it expresses, a k with two point sets, a ray with a mesh, two placed meshes, a disc
// with walls).
#pragma once

#include <optional>
#include <string>

#include "harness/model/oracle.h"
#include "oracle/cgal/cgal_audit.h"

namespace cc::cgal {

/// What the audit of one case found.
enum class AuditOutcome {
  agree,            // CGAL gives the exact reference's answer and, where it computes them, the sign of
                    // its margin, of every k-DOP slab's overlap (exact_kdop_slabs), a disc's walls
                    // touched, two meshes' pairs of faces that meet, a ray's faces hit and its first t (the reference's t one of the two
                    // doubles around CGAL's, the upper end of its range the smallest double >= CGAL's)
  disagree,         // it does not: one of the two is wrong (class exact_defect)
  out_of_contract,  // the inputs are outside the library's contract: not compared
  undecided,        // the exact reference cannot decide the case: not compared
};

struct Audit {
  AuditOutcome outcome = AuditOutcome::agree;
  harness::ExactVerdict exact;
  CgalAnswer cgal;  // when compared
  std::string why;  // what differs, for a disagreement
  /// Compared, and the exact reference's margin is 0 with a hit: the shapes touch.
  bool touching() const;
};

/// Whether CGAL answers the kind: cgal_answer takes its input's fields, in their order.
bool answers(harness::QueryKind kind);

/// CGAL's answer to an input in the library's contract; nothing for a kind it does not answer.
std::optional<CgalAnswer> cgal_answer(const harness::Input& input);

/// The case through the exact reference and CGAL (of a kind CGAL answers, see answers()).
Audit audit_case(const harness::Input& input, const harness::ExactReference& exact);

}  // namespace cc::cgal
