// What a vkpt-bench run measured, by key ("cpu_primary_mrays_s": null where not
// measured), and its forms: one JSON object, a row of bench/README.md's table, or lines.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace vkpt::internal::bench {

struct Report {
  std::map<std::string, std::optional<double>> numbers;
  std::string device;
  unsigned threads = 0;

  void Set(const std::string& key, std::optional<double> v) { numbers[key] = v; }
  std::optional<double> Get(const std::string& key) const {
    auto it = numbers.find(key);
    return it == numbers.end() ? std::nullopt : it->second;
  }
};

void PrintJson(const Report& r);
// GPU cam | GPU diff | Embree cam | Embree diff | CPU PT | GPU PT | mismatches | … of
// bench/README.md's table, for `scene`.
void PrintMarkdownRow(const Report& r, const std::string& scene);
void PrintTable(const Report& r);

}  // namespace vkpt::internal::bench
