// `polymech plan` (issue 38): the subcommand's entry point (apps/polymech/plan.cpp).
#pragma once

#include <filesystem>

namespace polymech::apps {

// argv[0] is "plan"; self_dir holds the apps the planned run uses.
int plan_main(int argc, char** argv, const std::filesystem::path& self_dir);

}  // namespace polymech::apps
