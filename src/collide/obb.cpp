#include "collide/obb.h"

#include <type_traits>

#include "collide/obb_bound.h"
#include "collide/record_sink.h"
#include "collide/simd_lanes.h"

namespace cc {
namespace {

// The separating-axis test, three axes at a time: T is simd::Triple<Scalar> or Triple<Avx2>,
// lane k holding the quantity of a's axis k (its face normal, or its edge crossed with each of
// b's) or of b's axis k. Every quantity is the plain floating-point expression written below, the
// same in every lane and instruction set, so the kernels answer alike bit for bit. Each axis
// separates when |projection| - (radius_a + radius_b) exceeds one bound for the whole test
// (bounds::ObbBound: the rounding, and the axes' deviation from orthonormal).
//
// Symmetric in a and b bit for bit: swapping them negates d exactly, transposes r (each entry is
// the same three products summed in the same order), and an edge axis separates only if it does
// in both boxes' frames (each frame's formula projects exactly onto a direction of its own, up to
// a sign and the rounding that the bound covers), so the swapped test evaluates the same
// expressions. Sums of three terms are plain left-to-right sums: permuting the world's axes
// changes their rounding, within the bound.
template <class T, class Records>
bool test(const Obb& a, const Obb& b, Records& records) {
  constexpr bool recording = !std::is_same_v<Records, bounds::NoRecords>;
  const Vec3 d = b.center - a.center;  // swapping a and b negates d exactly
  const auto sum = [](const Vec3& v) { return v.x + v.y + v.z; };
  const bounds::ObbBound bound{sum(abs(d)), sum(a.half), sum(b.half)};
  records.add(bounds::ObbTest{{a, {}}, {b, {}}, bound});
  const T error = T::broadcast(bound.total());
  const T dx = T::broadcast(d.x), dy = T::broadcast(d.y), dz = T::broadcast(d.z);
  const Vec3 *ac = a.axes.col, *bc = b.axes.col;
  // v.x x + v.y y + v.z z, v read from memory (one broadcast each).
  const auto combine = [](const Vec3& v, const T& x, const T& y, const T& z) {
    return T::broadcast_from(&v.x) * x + T::broadcast_from(&v.y) * y + T::broadcast_from(&v.z) * z;
  };

  // a's face normals (lane i): the projection a_i . d, radius_b = sum_j b_j |r[i][j]| with
  // r[i][j] = a_i . b_j taken by columns (lane i).
  T ax, ay, az;
  T::transpose(ac, ax, ay, az);
  const T ta = ax * dx + ay * dy + az * dz;
  T col[3], abs_col[3];
  for (int j = 0; j < 3; ++j) col[j] = combine(bc[j], ax, ay, az), abs_col[j] = abs(col[j]);
  const T ha = T::load(a.half);
  const T rb_faces = combine(b.half, abs_col[0], abs_col[1], abs_col[2]);
  if constexpr (recording) {
    double p[4], ra[4], rb[4];
    ta.store(p), ha.store(ra), rb_faces.store(rb);
    for (int i = 0; i < 3; ++i) records.add(bounds::ObbAxis{i, 0, p[i], 0, ra[i], rb[i]});
  }
  if (T::bits(abs(ta) - (ha + rb_faces) > error) != 0) return false;

  // (Most pairs a test meets apart are apart along a's normals. The rest reads its inputs again
  // rather than keep in registers, or spill, what they read before knowing whether it is needed:
  // a barrier to the compiler, no instruction.)
  asm volatile("" ::: "memory");
  // b's face normals (lane j), with r by rows (lane j): the columns transposed.
  T bx, by, bz;
  T::transpose(bc, bx, by, bz);
  const T tb = bx * dx + by * dy + bz * dz;
  T row[3], abs_row[3];
  T::transpose(col[0], col[1], col[2], row);
  T::transpose(abs_col[0], abs_col[1], abs_col[2], abs_row);
  const T hb = T::load(b.half);
  const T ra_faces = combine(a.half, abs_row[0], abs_row[1], abs_row[2]);
  if constexpr (recording) {
    double p[4], ra[4], rb[4];
    tb.store(p), ra_faces.store(ra), hb.store(rb);
    for (int j = 0; j < 3; ++j) records.add(bounds::ObbAxis{3 + j, 0, p[j], 0, ra[j], rb[j]});
  }
  if (T::bits(abs(tb) - (ra_faces + hb) > error) != 0) return false;

  // The edge axes a_i x b_j, lane j: d . (a_i x b_j) in a's frame and in b's frame.
  double t_a[4];
  ta.store(t_a);
  const T tb1 = tb.rotate1(), tb2 = tb.rotate2(), hb1 = hb.rotate1(), hb2 = hb.rotate2();
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    const T in_a = T::broadcast_from(&t_a[i2]) * row[i1] - T::broadcast_from(&t_a[i1]) * row[i2];
    const T in_b = row[i].rotate2() * tb1 - row[i].rotate1() * tb2;
    const T ra = T::broadcast(a.half[i1]) * abs_row[i2] + T::broadcast(a.half[i2]) * abs_row[i1];
    const T rb = hb1 * abs_row[i].rotate2() + hb2 * abs_row[i].rotate1();
    if constexpr (recording) {
      double pa[4], pb[4], r_a[4], r_b[4];
      in_a.store(pa), in_b.store(pb), ra.store(r_a), rb.store(r_b);
      for (int j = 0; j < 3; ++j) {
        records.add(bounds::ObbAxis{6 + 3 * i + j, 0, pa[j], 0, r_a[j], r_b[j]});
        records.add(bounds::ObbAxis{6 + 3 * i + j, 1, pb[j], 0, r_a[j], r_b[j]});
      }
    }
    if (T::bits(min(abs(in_a), abs(in_b)) - (ra + rb) > error) != 0) return false;
  }
  // On the hit path only: inputs outside the contract give false.
  return in_domain(a) && in_domain(b);
}

[[gnu::flatten]] bool test_scalar(const Obb& a, const Obb& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Scalar>>(a, b, none);
}

[[gnu::target("avx2"), gnu::flatten]] bool test_avx2(const Obb& a, const Obb& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Avx2>>(a, b, none);
}

// The AVX2 triples again, compiled for AVX-512 processors, which lend them 32 vector registers.
[[gnu::target("avx512f,avx512dq,avx512vl"), gnu::flatten]] bool test_avx512(const Obb& a, const Obb& b) {
  bounds::NoRecords none;
  return test<simd::Triple<simd::Avx2>>(a, b, none);
}

}  // namespace

bool test_obb_obb(const Obb& a, const Obb& b) {
  switch (simd::selected()) {
    case simd::Kernel::scalar: return test_scalar(a, b);
    case simd::Kernel::avx2: return test_avx2(a, b);
    case simd::Kernel::avx512: return test_avx512(a, b);
  }
  return test_scalar(a, b);
}

bool test_obb_obb(const Obb& a, const Obb& b, bounds::Records& records) {
  bounds::RecordsRef into{records};
  return test<simd::Triple<simd::Scalar>>(a, b, into);
}

}  // namespace cc
