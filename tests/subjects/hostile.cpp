// Subjects that misbehave the ways real code does by accident, one fault each, chosen when the
// file is built (HOSTILE_<FAULT>). Each answers aabb_aabb (rightly, touching counts, unless the
// fault is in the answer) and sphere_sphere (rightly), so that a run has something to judge;
// the fault strikes in aabb_aabb, or while loading:
//   EXITS         exit(0) on every call          EXITS_NONZERO  _exit(3) on every call
//   ABORTS        abort() on every call          PRINTS         printf without a newline (and a
//                                                               byte not UTF-8), and a line on
//                                                               stderr, every call
//   CLOSES_FDS    closes descriptors 3..1023     WRITES_FDS     writes a byte to descriptors 3..63
//   WRONG         touching boxes are a miss      LOAD_ABORTS    abort() in a constructor
//   LOAD_EXITS    _exit(0) in a constructor      LOAD_HANGS     crosscheck_subject_version hangs
//   WRONG_LATER   right on its first 100 calls in a process, touching boxes a miss after (an answer
//                 that depends on what the process did before)
#include <crosscheck/subject.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {

#if defined(HOSTILE_WRONG_LATER)
int calls = 0;
#endif

bool overlap(double a_lo, double a_hi, double b_lo, double b_hi) {
#if defined(HOSTILE_WRONG)
  return a_lo < b_hi && b_lo < a_hi;
#elif defined(HOSTILE_WRONG_LATER)
  return calls > 100 ? a_lo < b_hi && b_lo < a_hi : a_lo <= b_hi && b_lo <= a_hi;
#else
  return a_lo <= b_hi && b_lo <= a_hi;
#endif
}

#if defined(HOSTILE_LOAD_ABORTS)
[[maybe_unused]] const int kLoading = (std::abort(), 0);
#elif defined(HOSTILE_LOAD_EXITS)
[[maybe_unused]] const int kLoading = (_exit(0), 0);
#endif

}  // namespace

extern "C" {

int crosscheck_subject_version(void) {
#if defined(HOSTILE_LOAD_HANGS)
  for (;;) pause();
#endif
  return CROSSCHECK_SUBJECT_VERSION;
}

int crosscheck_aabb_aabb(const cc_aabb* a, const cc_aabb* b) {
#if defined(HOSTILE_WRONG_LATER)
  ++calls;
#endif
#if defined(HOSTILE_EXITS)
  std::exit(0);
#elif defined(HOSTILE_EXITS_NONZERO)
  _exit(3);
#elif defined(HOSTILE_ABORTS)
  std::abort();
#elif defined(HOSTILE_PRINTS)
  std::printf("checking boxes at %g \xff", a->lo.x);  // no newline, and a byte that is not UTF-8
  std::fprintf(stderr, "aabb_aabb called\n");
#elif defined(HOSTILE_CLOSES_FDS)
  for (int fd = 3; fd < 1024; ++fd) close(fd);
#elif defined(HOSTILE_WRITES_FDS)
  for (int fd = 3; fd < 64; ++fd) (void)!write(fd, "x", 1);
#endif
  return overlap(a->lo.x, a->hi.x, b->lo.x, b->hi.x) && overlap(a->lo.y, a->hi.y, b->lo.y, b->hi.y) &&
         overlap(a->lo.z, a->hi.z, b->lo.z, b->hi.z);
}

}  // extern "C"
