// The custom mutator (libFuzzer builds only: it falls back on LLVMFuzzerMutate).
#include <cmath>
#include <cstring>
#include <limits>

#include "fuzz/fuzz_target.h"
#include "harness/generation/choices.h"
#include "harness/formats/fuzz_record.h"
#include "harness/generation/touch.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace cc::fuzz {
namespace {

using namespace harness;

// The special values a coordinate may become.
constexpr double kSpecial[] = {0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 0x1p-30, 0x1p30, 0x1p-1074, 0x1p-1022, 0x1.fffffffffffffp1023,
                               0x1p300, 0x1p-300, std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()};

// The mutated record in place of the input, or libFuzzer's own mutation when it does not fit.
std::size_t written(const std::vector<std::uint8_t>& bytes, std::uint8_t* data, std::size_t size, std::size_t max_size) {
  if (bytes.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, bytes.data(), bytes.size());
  return bytes.size();
}

}  // namespace

std::size_t mutate(QueryKind kind, std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
  RandomChoices c(seed);
  const Input input = decode_record(kind, {data, size});
  std::vector<double> values = record_values(input);
  const auto pick = [&] { return static_cast<std::size_t>(c.draw(values.size())); };
  switch (values.empty() ? 5 : c.draw(7)) {
    case 0: values[pick()] = values[pick()]; break;  // copy one coordinate into another
    case 1: {                                        // step a value by 1 to 4 ULPs
      double& x = values[pick()];
      const double toward = c.chance(50) ? INFINITY : -INFINITY;
      for (std::uint64_t i = 0, n = 1 + c.draw(4); i < n; ++i) x = std::nextafter(x, toward);
      break;
    }
    case 2: values[pick()] = kSpecial[c.draw(std::size(kSpecial))]; break;  // a special value
    case 3: {                                                                 // flip a sign
      double& x = values[pick()];
      x = -x;
      break;
    }
    case 4: {  // move one shape so that it touches the other: its own record, as touch may
               // change the record's shape (a second box put into a frame that had one)
      ValueSource source(c, {});
      Input touched = input;
      make_touching(touched, source);
      return written(encode_record(touched), data, size, max_size);
    }
    default: return LLVMFuzzerMutate(data, size, max_size);
  }
  const Input mutated = with_record_values(input, values);
  std::vector<std::uint8_t> bytes = encode_record(mutated);
  // Keep the flags and the header bytes of the original record (they read the same); the rest is
  // the mutated values.
  const std::size_t header = bytes.size() - 8 * record_values(mutated).size();
  for (std::size_t i = 0; i < header && i < size; ++i) bytes[i] = data[i];
  return written(bytes, data, size, max_size);
}

}  // namespace cc::fuzz
