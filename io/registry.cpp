#include "io/registry.hpp"

#include "io/dem_pour_scene.hpp"
#include "io/dem_scene.hpp"
#include "io/efg_scene.hpp"
#include "io/flow_scene.hpp"
#include "io/helmholtz_scene.hpp"
#include "io/isph_scene.hpp"
#include "io/mps_elastic_scene.hpp"
#include "io/nosb_pd_scene.hpp"
#include "io/piezo_scene.hpp"
#include "io/solid_scene.hpp"

namespace polymech::io {

namespace {

// The app of a scene is read off its text, without the loader (which checks the stability limits with the
// models' kernels, so it needs Kokkos): the app then loads and checks the whole scene itself (issue 32).
std::string mps_app(const std::filesystem::path& file) {
  return Scene::load(file).root().optional_table("crack") ? "mps_harmonics" : "mps_point_source";
}

std::string pd_app(const std::filesystem::path& file) {
  const auto load = Scene::load(file).root().optional_table("loading");
  return load && load->choice("kind", {"none", "tension", "impact"}) == "tension" ? "pd_tension" : "pd_penetration";
}

}  // namespace

const std::vector<SceneKind>& scene_kinds() {
  static const std::vector<SceneKind> kinds = {
      {"mps_elastic", "MPS elastic waves in 2D plane strain, with crack-face contact (seed 000)",
       {"mps_point_source", "mps_harmonics"}, [](const std::filesystem::path& f) { load_mps_elastic_scene(f); }, mps_app,
       [](const std::filesystem::path& f) { return load_mps_elastic_scene(f).cost; }},
      {"nosb_pd", "non-ordinary state-based peridynamics, tension and plate perforation (seed 003)",
       {"pd_tension", "pd_penetration"}, [](const std::filesystem::path& f) { load_nosb_pd_scene(f); }, pd_app,
       [](const std::filesystem::path& f) { return load_nosb_pd_scene(f).cost; }},
      {"helmholtz", "matrix-free high-order FEM Helmholtz (seed 002 paper 3)", {"helmholtz"},
       [](const std::filesystem::path& f) { load_helmholtz_scene(f); },
       [](const std::filesystem::path&) { return std::string("helmholtz"); },
       [](const std::filesystem::path& f) { return load_helmholtz_scene(f).cost; }},
      {"dem", "DEM spheres, Hertz-Mindlin contact against planes and FE surfaces (seed 002 paper 2)", {"dem_benchmark"},
       [](const std::filesystem::path& f) { load_dem_scene(f); },
       [](const std::filesystem::path&) { return std::string("dem_benchmark"); },
       [](const std::filesystem::path& f) { return load_dem_scene(f).cost; }},
      {"dem_pour", "DEM gravel (multi-sphere clumps or spheres) poured into a bin (seed 002 paper 2)", {"dem_pour"},
       [](const std::filesystem::path& f) { load_dem_pour_scene(f); },
       [](const std::filesystem::path&) { return std::string("dem_pour"); },
       [](const std::filesystem::path& f) { return load_dem_pour_scene(f).cost; }},
      {"efg", "element-free Galerkin cracked plates, MLS + J-integral (seed 004)", {"efg"},
       [](const std::filesystem::path& f) { load_efg_scene(f); },
       [](const std::filesystem::path&) { return std::string("efg"); },
       [](const std::filesystem::path& f) { return load_efg_scene(f).cost; }},
      {"isph", "stabilized ISPH with IGCB walls: hydrostatic tank, dam break (seed 002 paper 4)", {"isph"},
       [](const std::filesystem::path& f) { load_isph_scene(f); },
       [](const std::filesystem::path&) { return std::string("isph"); },
       [](const std::filesystem::path& f) { return load_isph_scene(f).cost; }},
      {"solid", "finite-element solids: the 8YSZ micro-cantilever, Hill plasticity, inverse study (seed 002 paper 5); Cook's membrane",
       {"micro_cantilever", "cook_membrane"},
       [](const std::filesystem::path& f) {
         if (solid_app(f) == "cook_membrane")
           load_cook_scene(f);
         else
           load_solid_scene(f);
       },
       solid_app,
       [](const std::filesystem::path& f) { return solid_app(f) == "cook_membrane" ? load_cook_scene(f).cost : load_solid_scene(f).cost; }},
      {"piezo", "finite-element piezoelectric harvester: static bender, load/frequency sweep, transient (seed 002 paper 1)",
       {"piezo_harvester"}, [](const std::filesystem::path& f) { load_piezo_scene(f); },
       [](const std::filesystem::path&) { return std::string("piezo_harvester"); },
       [](const std::filesystem::path& f) { return load_piezo_scene(f).cost; }},
      {"flow", "incompressible Navier-Stokes, Taylor-Hood: the Turek-Hron CFD and FSI tests, the flow-driven piezoelectric harvester (seed 002 paper 1, issue 36)",
       {"turek_hron"}, [](const std::filesystem::path& f) { load_flow_scene(f); },
       [](const std::filesystem::path&) { return std::string("turek_hron"); },
       [](const std::filesystem::path& f) { return load_flow_scene(f).cost; }},
  };
  return kinds;
}

const SceneKind& scene_kind_of(const std::filesystem::path& file) {
  const Scene scene = Scene::load(file);
  const SceneTable root = scene.root();
  std::vector<std::string> names;
  for (const auto& k : scene_kinds()) names.push_back(k.kind);
  const std::string kind = root.table("model").choice("kind", names);
  for (const auto& k : scene_kinds())
    if (k.kind == kind) return k;
  throw SceneError(file.string() + ": unknown model kind '" + kind + "'");  // unreachable: choice() checked it
}

}  // namespace polymech::io
