// crosscheck bands: the tolerance band table.
#include <cstdio>

#include "harness/judging/bands.h"
#include "harness/formats/number_text.h"
#include "oracle/peers/peer_opinions.h"
#include "tool/commands.h"

namespace cc::tool {

void add_bands_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("bands", "Print the tolerance bands, per query for the library and per second-opinion party");
  cmd->callback([&exit_code] {
    std::printf("%-46s %-13s %-10s %-9s %s\n", "party", "sides", "width", "t width", "why");
    for (const auto& [party, band] : harness::all_bands(peers::PeerOpinions())) {
      const std::string width = band.width == 0 ? "0" : "2^" + std::to_string(std::ilogb(band.width));
      const std::string t = band.param_width == 0 ? "-" : "2^" + std::to_string(std::ilogb(band.param_width));
      std::printf("%-46s %-13s %-10s %-9s %s\n", party.c_str(), std::string(to_string(band.sides)).c_str(),
                  width.c_str(), t.c_str(), std::string(band.why).c_str());
    }
    std::printf("\nWidths are in units of the exact margin: a distance (or depth) divided by the largest input\n"
                "coordinate. conservative: only a hit for shapes apart by at most the width is tolerated.\n");
    exit_code = 0;
  });
}

}  // namespace cc::tool
