// Runs any scene: reads its [model].kind, finds the kind's loader and runner in the registry
// (io/registry.hpp), checks the scene, and hands the whole command line to the app that runs it
// (mps_point_source or mps_harmonics, pd_tension or pd_penetration, helmholtz), next to this binary.
//   polymech --scene scenes/pd/penetration_303.toml [the app's options ...]
//   polymech --scene scenes/pd/penetration_303.toml --help    (the help of the app that runs it)
//   polymech --list
//   polymech --version
//   polymech plan --scene FILE --target-error E [--quantity KEY] [--run]   (apps/polymech/plan.cpp, issue 38)
// The app checks the options; its first line on stderr is then the notice "[polymech] SCENE -> APP"
// (POLYMECH_DISPATCH_NOTICE, apps/common/cli.hpp), or its one-line error.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/app.hpp"
#include "apps/polymech/plan.hpp"
#include "io/registry.hpp"

namespace pm = polymech;

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "plan")
    return pm::apps::plan_main(argc - 1, argv + 1, std::filesystem::path(argv[0]).parent_path());
  std::string scene;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--scene" && k + 1 < argc) scene = argv[k + 1];
    if (a.rfind("--scene=", 0) == 0) scene = a.substr(8);
  }
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    // with a scene, --help is the help of the app that runs it (issue 33 item 10): handed on below
    if (a == "--list" || (scene.empty() && (a == "--help" || a == "-h"))) {
      std::printf("polymech --scene FILE [options of the app that runs it]\n"
                  "polymech plan --scene FILE --target-error E [--quantity KEY] [--run]   (polymech plan --help)\n"
                  "scene kinds:\n");
      for (const auto& kind : pm::io::scene_kinds()) {
        std::string apps;
        for (const auto& app : kind.apps) apps += (apps.empty() ? "" : ", ") + app;
        std::printf("  %-12s %s (apps: %s)\n", kind.kind.c_str(), kind.description.c_str(), apps.c_str());
      }
      return 0;
    }
    if (a == "--version") {
      std::printf("%s\n", pm::apps::version_line("polymech").c_str());
      return 0;
    }
  }
  if (scene.empty()) {
    std::fprintf(stderr, "polymech: error: give --scene FILE (polymech --list shows the scene kinds)\n");
    return 2;
  }
  std::error_code ec;
  const auto st = std::filesystem::status(scene, ec);
  if (!std::filesystem::exists(st) || std::filesystem::is_directory(st)) {
    std::fprintf(stderr, "polymech: error: --scene %s: %s\n", pm::apps::cli::shown(scene).c_str(),
                 std::filesystem::exists(st) ? "is a folder, not a scene file" : "scene file not found");
    return 2;
  }
  std::string app;
  const int rc = pm::apps::guarded("polymech", [&] {
    const pm::io::SceneKind& kind = pm::io::scene_kind_of(scene);  // the scene's text only: no Kokkos, no kernels
    app = kind.app_for(scene);
    return 0;
  });
  if (rc != 0) return rc;
  const std::filesystem::path self = std::filesystem::path(argv[0]).parent_path();
  const std::string exe = (self.empty() ? std::filesystem::path(app) : self / app).string();
  std::vector<char*> args = {const_cast<char*>(exe.c_str())};
  for (int k = 1; k < argc; ++k) args.push_back(argv[k]);
  args.push_back(nullptr);
  const std::string notice = "[polymech] " + scene + " -> " + app;
  setenv("POLYMECH_DISPATCH_NOTICE", notice.c_str(), 1);
  execv(exe.c_str(), args.data());
  std::fprintf(stderr, "polymech: failed: cannot run %s: %s\n", exe.c_str(), std::strerror(errno));
  return 1;
}
