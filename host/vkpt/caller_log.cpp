#include "vkpt/caller_log.h"

#include "vkpt/api_terms.h"

namespace vkpt::internal {
namespace {

std::function<void(const std::string&)> At(const vkpt::LogCallback& log, vkpt::LogLevel level) {
  if (!log) return {};
  return [log, level](const std::string& message) { log(level, InApiTerms(message)); };
}

}  // namespace

EngineLog EngineLogOf(const vkpt::LogCallback& log) {
  return {At(log, vkpt::LogLevel::Warning), At(log, vkpt::LogLevel::Info), At(log, vkpt::LogLevel::Debug)};
}

ClientView LoggedView(const vkpt::LogCallback& log) {
  ClientView view;
  view.log = EngineLogOf(log);
  view.warning = At(log, vkpt::LogLevel::Warning);
  view.report = At(log, vkpt::LogLevel::Debug);
  return view;
}

void LogLoad(const vkpt::LogCallback& log, const Scene& scene) {
  if (!log) return;
  for (const std::string& w : scene.warnings) log(vkpt::LogLevel::Warning, InApiTerms(scene.path + ": " + w));
  for (const std::string& f : scene.ignoredFeatures)
    log(vkpt::LogLevel::Warning, InApiTerms(scene.path + ": ignored: " + f));
}

}  // namespace vkpt::internal
