#include "oracle/cgal/exact_audit.h"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "harness/formats/number_text.h"
#include "harness/judging/classify.h"
#include "oracle/exact/exact_kdops.h"

namespace cc::cgal {
namespace {

// The input's fields, in their order, as arguments of f.
template <class In, class F>
decltype(auto) with_fields(const In& in, F&& f) {
  return std::apply([&](const auto&... field) -> decltype(auto) { return f(field.of(in)...); }, harness::Fields<In>::list);
}

// Whether cgal_answer takes an In's fields I..., in their order.
template <class In, std::size_t... I>
constexpr bool takes_fields(std::index_sequence<I...>) {
  return requires(const In& in) { cgal_answer(std::get<I>(harness::Fields<In>::list).of(in)...); };
}

// An input whose fields, in their order, cgal_answer takes: CGAL answers kinds by what their
// inputs are made of, not by their names.
template <class In>
concept Answered =
    takes_fields<In>(std::make_index_sequence<std::tuple_size_v<std::remove_cv_t<decltype(harness::Fields<In>::list)>>>{});

int sign_of(double margin) { return (margin > 0) - (margin < 0); }

std::string signs_text(const std::vector<int>& signs) {
  std::string text;
  for (int s : signs) text += s > 0 ? '+' : (s < 0 ? '-' : '0');
  return text;
}

// What differs beyond the hit and the margin's sign, for inputs with more to compare (found by
// their fields, as cgal_answer finds them): none for most.
template <class... Fields>
std::string slab_differences(const CgalAnswer&, const Fields&...) {
  return {};
}

// Two point sets with a k: the sign of every slab's overlap, against those of exact_kdop_slabs
// (which takes non-empty sets only).
std::string slab_differences(const CgalAnswer& cgal, int k, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.empty() || b.empty()) return {};
  std::vector<int> exact_signs;
  for (const exact::ExactSlab& s : exact::exact_kdop_slabs(k, a, b)) exact_signs.push_back(sgn(s.overlap));
  if (exact_signs == cgal.slab_signs) return {};
  return "exact reference's slab overlap signs " + signs_text(exact_signs) + " differ from CGAL's " +
         signs_text(cgal.slab_signs) + " (directions of k = " + std::to_string(k) + " in order)";
}

std::string faces_text(const std::vector<std::uint32_t>& faces) {
  std::string text = "{";
  for (std::size_t i = 0; i < faces.size(); ++i) text += (i > 0 ? ", " : "") + std::to_string(faces[i]);
  return text + "}";
}

// Where CGAL gives the faces a ray meets (or the walls a disc touches): those, every one; for a
// ray's hit, the first t: the upper end of the exact reference's range must be CGAL's smallest
// double >= t, and its t one of the two doubles around t.
std::string face_differences(const harness::ExactVerdict& exact, const CgalAnswer& cgal) {
  if (!cgal.faces) return {};
  std::vector<std::uint32_t> exact_faces;
  for (const harness::FacePair& pair : exact.answer.pairs) exact_faces.push_back(pair.first);
  std::sort(exact_faces.begin(), exact_faces.end());
  if (exact_faces != *cgal.faces) {
    return "exact reference's faces hit " + faces_text(exact_faces) + " differ from CGAL's " + faces_text(*cgal.faces);
  }
  if (!cgal.first_t) return {};
  const Bracket& t = *cgal.first_t;
  const std::string cgal_t = "CGAL's first t lies in [" + harness::format_double(t.down) + ", " +
                             harness::format_double(t.up) + "]";
  if (exact.answer.params.empty() || exact.param_ranges.empty()) return "exact reference gives no first t, " + cgal_t;
  const double exact_t = exact.answer.params[0], exact_upper = exact.param_ranges[0].second;
  if (exact_upper == t.up && (exact_t == t.down || exact_t == t.up)) return {};
  return "exact reference's first t " + harness::format_double(exact_t) + " (allowed up to " +
         harness::format_double(exact_upper) + "): " + cgal_t;
}

std::string pairs_text(const std::vector<harness::FacePair>& pairs) {
  std::string text = "{";
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    text += (i > 0 ? ", (" : "(") + std::to_string(pairs[i].first) + ", " + std::to_string(pairs[i].second) + ")";
  }
  return text + "}";
}

// Where CGAL gives the pairs of faces of two meshes that meet: those, every one.
std::string pair_differences(const harness::ExactVerdict& exact, const CgalAnswer& cgal) {
  if (!cgal.pairs) return {};
  std::vector<harness::FacePair> exact_pairs = exact.answer.pairs;
  std::sort(exact_pairs.begin(), exact_pairs.end());
  if (exact_pairs == *cgal.pairs) return {};
  return "exact reference's pairs that meet " + pairs_text(exact_pairs) + " differ from CGAL's " + pairs_text(*cgal.pairs);
}

// Where CGAL gives a distance (Judged::distance): the exact reference's, rounded down, is CGAL's
// rounded down.
std::string distance_differences(const harness::ExactVerdict& exact, const CgalAnswer& cgal) {
  if (!cgal.distance_down) return "CGAL gives no distance";
  if (exact.answer.params.size() != 1) return "the exact reference gives no distance";
  if (exact.answer.params[0] == *cgal.distance_down) return {};
  return "exact reference's distance " + harness::format_double(exact.answer.params[0]) + ", CGAL's " +
         harness::format_double(*cgal.distance_down) + " (both rounded down)";
}

// Where CGAL gives the corners of two triangles' intersection and the exact reference gives them
// too (Judged::corners): the same corners, each exact corner one of the doubles around CGAL's.
std::string corner_differences(const harness::ExactVerdict& exact, const CgalAnswer& cgal) {
  const std::vector<double>& params = exact.answer.params;
  if (cgal.corners.empty() || params.empty()) return {};
  const auto text = [&] {
    std::string t = "exact reference's corners";
    for (double v : params) {
      t += " ";
      t += harness::format_double(v);
    }
    t += " differ from CGAL's";
    for (const auto& c : cgal.corners) {
      t += " (";
      for (int k = 0; k < 3; ++k) {
        if (k > 0) t += ", ";
        t += harness::format_double(c[k].down);
        t += "..";
        t += harness::format_double(c[k].up);
      }
      t += ")";
    }
    return t;
  };
  if (params.size() != 3 * cgal.corners.size()) return text();
  // Each exact corner matched to a CGAL corner of its own: a bracket holds two doubles, so
  // corners one ulp apart may match either way (tried by backtracking; six corners at most).
  const auto around = [](double v, const Bracket& b) { return v == b.down || v == b.up; };
  const std::size_t n = cgal.corners.size();
  std::vector<bool> used(n, false);
  const std::function<bool(std::size_t)> match = [&](std::size_t i) {
    if (i == n) return true;
    for (std::size_t j = 0; j < n; ++j) {
      const auto& c = cgal.corners[j];
      if (used[j] || !around(params[3 * i], c[0]) || !around(params[3 * i + 1], c[1]) || !around(params[3 * i + 2], c[2])) continue;
      used[j] = true;
      if (match(i + 1)) return true;
      used[j] = false;
    }
    return false;
  };
  if (!match(0)) return text();
  return {};
}

}  // namespace

bool answers(harness::QueryKind kind) {
  return harness::with_kind(kind, []<class In>() { return Answered<In>; });
}

std::optional<CgalAnswer> cgal_answer(const harness::Input& input) {
  return std::visit(
      []<class In>(const In& in) -> std::optional<CgalAnswer> {
        if constexpr (Answered<In>) {
          return with_fields(in, [](const auto&... fields) { return cgal_answer(fields...); });
        } else {
          return std::nullopt;
        }
      },
      input);
}

bool Audit::touching() const {
  return (outcome == AuditOutcome::agree || outcome == AuditOutcome::disagree) && exact.margin == 0 &&
         exact.answer.hit;
}

Audit audit_case(const harness::Input& input, const harness::ExactReference& exact) {
  Audit a;
  a.exact = exact.judge(input);
  if (a.exact.contract != harness::Contract::in) {
    a.outcome = AuditOutcome::out_of_contract;
    return a;
  }
  if (!a.exact.decided) {
    a.outcome = AuditOutcome::undecided;
    return a;
  }
  const std::optional<CgalAnswer> cgal = cgal_answer(input);
  if (!cgal) throw std::invalid_argument("audit_case: CGAL does not answer " + std::string(harness::name(harness::kind_of(input))));
  a.cgal = *cgal;
  const auto says = [](bool hit) { return hit ? "hit" : "miss"; };
  if (a.cgal.hit != a.exact.answer.hit) {
    a.why = std::string("exact reference says ") + says(a.exact.answer.hit) + ", CGAL says " + says(a.cgal.hit);
  } else if (a.cgal.margin_sign && *a.cgal.margin_sign != sign_of(a.exact.margin)) {
    a.why = "exact reference's margin " + harness::format_double(a.exact.margin) + " has not the sign of CGAL's " +
            std::to_string(*a.cgal.margin_sign);
  } else {
    a.why = std::visit(
        [&a](const auto& in) { return with_fields(in, [&a](const auto&... fields) { return slab_differences(a.cgal, fields...); }); },
        input);
    if (a.why.empty()) a.why = face_differences(a.exact, a.cgal);
    if (a.why.empty() && harness::judged_of(harness::kind_of(input)) != harness::Judged::distance) {
      a.why = pair_differences(a.exact, a.cgal);
    }
    if (a.why.empty() && harness::judged_of(harness::kind_of(input)) == harness::Judged::corners) {
      a.why = corner_differences(a.exact, a.cgal);
    }
    if (a.why.empty() && harness::judged_of(harness::kind_of(input)) == harness::Judged::distance) {
      a.why = distance_differences(a.exact, a.cgal);
    }
  }
  a.outcome = a.why.empty() ? AuditOutcome::agree : AuditOutcome::disagree;
  return a;
}

}  // namespace cc::cgal
