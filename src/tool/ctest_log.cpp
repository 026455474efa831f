#include "tool/ctest_log.h"

#include <regex>
#include <sstream>

namespace cc::tool {
namespace {

// A result line: "  3/9 Test  #12: name ..........   Passed    0.40 sec" or "...***Failed  0.1 sec".
const std::regex& result_line() {
  static const std::regex r(R"(Test +#[0-9]+: (\S+) .*?(\*\*\*([A-Za-z]+)|Passed +([0-9.]+) sec))");
  return r;
}

}  // namespace

std::map<std::string, double> passed_test_seconds(const std::string& log) {
  std::map<std::string, double> out;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, result_line()) && m[4].matched) out[m[1].str()] = std::stod(m[4].str());
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> failed_tests(const std::string& log) {
  std::vector<std::pair<std::string, std::string>> out;
  std::istringstream in(log);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, result_line()) && m[3].matched && m[3].str() != "Skipped") {
      out.emplace_back(m[1].str(), m[3].str());
    }
  }
  return out;
}

void RunningTest::feed(std::string_view more) {
  static const std::regex start(R"(^ *Start +[0-9]+: (\S+))");
  partial_ += more;
  for (std::size_t end = partial_.find('\n'); end != std::string::npos; end = partial_.find('\n')) {
    const std::string line = partial_.substr(0, end);
    partial_.erase(0, end + 1);
    std::smatch m;
    if (std::regex_search(line, m, start)) {
      running_ = m[1].str();
    } else if (std::regex_search(line, m, result_line()) && running_ == m[1].str()) {
      running_.reset();
    }
  }
}

}  // namespace cc::tool
