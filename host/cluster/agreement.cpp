#include "cluster/agreement.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "util/error.h"

namespace vkpt::internal {

int AgreeOnOutcome(Cluster& cluster, int status, const std::string& message, const char* kind) {
  const std::vector<std::string> all = cluster.Gather(std::to_string(status) + ":" + message);
  const int worst = cluster.MaxOf(status);
  if (worst == 0 || cluster.Rank() != 0) return worst;
  std::vector<std::pair<std::string, std::vector<int>>> distinct;  // message, its ranks
  for (int r = 0; r < int(all.size()); ++r) {
    if (all[r].rfind("0:", 0) == 0) continue;
    const std::string text = all[r].substr(all[r].find(':') + 1);
    auto it = std::find_if(distinct.begin(), distinct.end(), [&](const auto& d) { return d.first == text; });
    if (it == distinct.end()) distinct.push_back({text, {r}});
    else it->second.push_back(r);
  }
  for (const auto& [text, ranks] : distinct) {
    if (ranks.size() == all.size()) {
      PrintError(kind, text);
    } else {
      for (int r : ranks) PrintError(kind, cluster.Name(r) + ": " + text);
    }
  }
  return worst;
}

}  // namespace vkpt::internal
