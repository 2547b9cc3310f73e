#include "scope_page.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace scenario {

extern const char* const kScopePageTemplate;  // scope_page.html, generated into the build

std::string scope_page(const nc::Scope& scope, const std::string& title) {
  nlohmann::json trace;
  trace["title"] = title;
  const std::span<const double> time = scope.time();
  trace["time"] = std::vector<double>(time.begin(), time.end());
  trace["channels"] = nlohmann::json::array();
  for (std::size_t i = 0; i < scope.channel_count(); ++i) {
    const nc::ScopeChannelInfo& info = scope.channel(i);
    if (!info.is_axis_signal ||
        std::find(std::begin(nc::kMotionSignals), std::end(nc::kMotionSignals), info.signal) ==
            std::end(nc::kMotionSignals)) {
      continue;
    }
    const std::span<const double> values = scope.values(i);
    trace["channels"].push_back({{"name", info.name},
                                 {"axis", info.axis_name},
                                 {"signal", std::string(nc::signal_name(info.signal))},
                                 {"unit", info.unit},
                                 {"values", std::vector<double>(values.begin(), values.end())}});
  }
  // Inside <script>, "</" could end the element: JSON allows "<\/" for it.
  std::string data = trace.dump();
  for (std::size_t at = data.find("</"); at != std::string::npos; at = data.find("</", at + 3))
    data.replace(at, 2, "<\\/");
  std::string page = kScopePageTemplate;
  // The template's data slot: `null` (a page that loads without a trace), marked for us.
  const std::string slot = "/*NCSDK_TRACE*/null";
  const std::size_t at = page.find(slot);
  if (at == std::string::npos) throw std::logic_error("scope page template without its data slot");
  page.replace(at, slot.size(), data);
  return page;
}

}  // namespace scenario
