// The command line's options as the library's settings (vkpt/vkpt.h): what the library
// checks, the command line checks (options.cpp), and what it renders with
// (scene_client.cpp). Beyond them the command line has its own (ClientScene,
// ClientView: vkpt/view.h).
#pragma once

#include "app/options.h"
#include "vkpt/settings_schema.h"

namespace vkpt::internal {

ApiSettings ApiSettingsOf(const Options& o);

}  // namespace vkpt::internal
