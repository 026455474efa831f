// A source of choices for the generators, in the spirit of Hypothesis: a generator draws small
// integers, and a draw of 0 always means the simplest option. Drawn at random the choices make
// a campaign; replayed from a vector that RapidCheck shrinks toward zeros they make a property
// whose counterexamples shrink toward simple values.
#pragma once

#include <cstdint>
#include <span>
#include <version>
#if defined(__cpp_lib_source_location)
#include <source_location>
#endif
#include <vector>

namespace cc::harness {

/// Where a generator draws: the file, line and column of the call that took current() as its
/// default argument. std::source_location where the standard library has it (GCC); clang 14,
/// which builds the fuzz targets, has it not with GCC 12's library, and its builtins serve.
class DrawSite {
 public:
#if defined(__cpp_lib_source_location)
  static constexpr DrawSite current(std::source_location site = std::source_location::current()) {
    return DrawSite(site.file_name(), site.line(), site.column());
  }
#else
  static constexpr DrawSite current(const char* file = __builtin_FILE(), unsigned line = __builtin_LINE(),
                                    unsigned column = __builtin_COLUMN()) {
    return DrawSite(file, line, column);
  }
#endif
  constexpr const char* file_name() const { return file_; }
  constexpr unsigned line() const { return line_; }
  constexpr unsigned column() const { return column_; }

 private:
  constexpr DrawSite(const char* file, unsigned line, unsigned column) : file_(file), line_(line), column_(column) {}
  const char* file_;
  unsigned line_, column_;
};

/// What a generator drew where, told while installed (record_draws): for the test that every
/// branch of every draw is taken.
class DrawRecorder {
 public:
  virtual ~DrawRecorder() = default;
  /// A draw in [0, n) gave `value` at `site`.
  virtual void drew(DrawSite site, std::uint64_t n, std::uint64_t value) = 0;
  /// A chance of `percent` came out `yes` at `site`.
  virtual void took_chance(DrawSite site, int percent, bool yes) = 0;
};

/// The recorder installed at first: it keeps nothing.
DrawRecorder& no_draw_recorder();

/// Installs `recorder` for this thread's draws; returns the one it replaces (to put back).
DrawRecorder& record_draws(DrawRecorder& recorder);

class Choices {
 public:
  virtual ~Choices() = default;
  /// A choice in [0, n) (n >= 1); 0 is the simplest. `site`: the generator's line that draws it.
  std::uint64_t draw(std::uint64_t n, DrawSite site = DrawSite::current());
  /// A choice made with probability about percent/100; false is the simplest (a draw of 0).
  bool chance(int percent, DrawSite site = DrawSite::current());

 private:
  virtual std::uint64_t choose(std::uint64_t n) = 0;
};

/// Choices from a seeded pseudo-random generator (xoshiro256**).
class RandomChoices final : public Choices {
 public:
  explicit RandomChoices(std::uint64_t seed);
  std::uint64_t next();

 private:
  std::uint64_t choose(std::uint64_t n) override;
  std::uint64_t s_[4];
};

/// Choices read from a recorded sequence (each taken modulo n); 0 once it runs out.
class ReplayChoices final : public Choices {
 public:
  explicit ReplayChoices(std::span<const std::uint64_t> recorded) : recorded_(recorded) {}

 private:
  std::uint64_t choose(std::uint64_t n) override;
  std::span<const std::uint64_t> recorded_;
  std::size_t next_ = 0;
};

/// A 64-bit mix of two values (splitmix64 finaliser), for deriving per-case seeds.
std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b);

}  // namespace cc::harness
