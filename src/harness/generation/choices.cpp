#include "harness/generation/choices.h"

namespace cc::harness {
namespace {

std::uint64_t splitmix(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

class NoDrawRecorder final : public DrawRecorder {
 public:
  void drew(DrawSite, std::uint64_t, std::uint64_t) override {}
  void took_chance(DrawSite, int, bool) override {}
};

// Never null: a draw tells whichever recorder is installed, without a test of its own.
thread_local DrawRecorder* t_recorder = &no_draw_recorder();

}  // namespace

DrawRecorder& no_draw_recorder() {
  static NoDrawRecorder none;
  return none;
}

DrawRecorder& record_draws(DrawRecorder& recorder) {
  DrawRecorder& before = *t_recorder;
  t_recorder = &recorder;
  return before;
}

std::uint64_t Choices::draw(std::uint64_t n, DrawSite site) {
  const std::uint64_t value = choose(n);
  t_recorder->drew(site, n, value);
  return value;
}

bool Choices::chance(int percent, DrawSite site) {
  const bool yes = choose(100) >= static_cast<std::uint64_t>(100 - percent);
  t_recorder->took_chance(site, percent, yes);
  return yes;
}

RandomChoices::RandomChoices(std::uint64_t seed) {
  for (auto& s : s_) s = splitmix(seed);
}

std::uint64_t RandomChoices::next() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

std::uint64_t RandomChoices::choose(std::uint64_t n) {
  return next() % n;  // the bias for n far below 2^64 is irrelevant here
}

std::uint64_t ReplayChoices::choose(std::uint64_t n) {
  if (next_ >= recorded_.size()) return 0;
  return recorded_[next_++] % n;
}

std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b) {
  std::uint64_t x = a ^ rotl(b, 32) ^ 0x2545f4914f6cdd1dULL;
  splitmix(x);
  return splitmix(x);
}

}  // namespace cc::harness
