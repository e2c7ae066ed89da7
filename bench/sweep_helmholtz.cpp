// Accuracy-cost sweep of the Helmholtz model (seed 002 paper 3): the paper's two verification cases and a
// higher-frequency one, for p = 1..4 over several element sizes, in double and float. Each run records
// the L2 error of eq. (28), DoFs, COCG iterations and the wall time of set-up and solve.
//
//   sweep_helmholtz [--cases cube,duct,duct_2khz] [--orders 1,2,3,4] [--precision double,float]
//                   [--max-dofs 8e5] [--float-tolerance 1e-6] [--out out/accuracy_cost] [--threads N]
//                   [--preconditioners jacobi,pmg,...] [--elements-x 16,80]
//
// Double runs use the paper's tolerance 1e-10 (Table 1). Float cannot reach it (its attainable
// relative residual is 1e-7 .. 1e-4 here); float runs use --float-tolerance, and where even that is
// out of reach COCG stops as `stagnated` (status 5) at the precision's floor, which the CSV records.
//
// --preconditioners runs every mesh once per preconditioner (column `preconditioner`: 0 none, 1 jacobi,
// 2 chebyshev, 3 pmg; its set-up time, included in solve_seconds, in `preconditioner_seconds`);
// --elements-x keeps only the meshes with these element counts along x.
// Writes <out>/helmholtz_<case>.csv (rewritten after every run, so a long sweep can be watched);
// tools/plot_helmholtz_accuracy_cost.py draws the Pareto plots and the "cheapest order" table.
// Cases: cube = scenes/helmholtz/cube.toml (500 Hz), duct = scenes/helmholtz/duct.toml (500 Hz),
// duct_2khz = the duct at 2 kHz (scenes/helmholtz/duct_2khz.toml): 5.8 wavelengths, pollution.
#include <cmath>
#include <ctime>
#include <cstdio>
#include <map>

#include "apps/common/app.hpp"
#include "helmholtz/helmholtz.hpp"
#include "io/helmholtz_scene.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

namespace {

struct Case {
  std::string name, scene;
  std::array<int, 3> aspect;                // element-count ratios (x : y : z) / the x count
  std::map<int, std::vector<int>> elements;  // order -> element counts along x
};

// Element counts along x; y and z follow the box's aspect (the duct: n, n/5, n/10).
const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
      {"cube", "scenes/helmholtz/cube.toml", {1, 1, 1},
       {{1, {4, 8, 16, 24, 32, 48, 64}}, {2, {2, 4, 8, 12, 16, 24, 32}}, {3, {2, 3, 4, 6, 8, 12, 16, 20}},
        {4, {2, 3, 4, 6, 8, 12, 16}}}},
      {"duct", "scenes/helmholtz/duct.toml", {1, 5, 10},
       {{1, {10, 20, 40, 80, 160, 320}}, {2, {10, 20, 40, 80, 160}}, {3, {10, 20, 40, 80}}, {4, {10, 20, 40, 80}}}},
      {"duct_2khz", "scenes/helmholtz/duct_2khz.toml", {1, 5, 10},
       {{1, {20, 40, 80, 160, 320}}, {2, {10, 20, 40, 80, 160}}, {3, {10, 20, 40, 80}}, {4, {10, 20, 40, 80}}}},
  };
  return c;
}

struct Row {
  double is_float, order, elements_x, h, dofs, status, iterations, restarts, true_residual, l2_error, setup, solve,
      wall, cpu, frequency, nodes_per_wavelength, preconditioner, preconditioner_seconds;
};

template <class T>
Row run_one(const pm::io::HelmholtzScene& scene) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  hz::Helmholtz<T> m(scene.config);
  const auto r = m.solve();
  // CPU time of the process (all threads): on a shared machine it is the robust cost measure, wall
  // time includes the time other jobs held the cores
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double h = m.mean_element_size();
  const auto& c = scene.config;
  return {sizeof(T) == 4 ? 1.0 : 0.0,
          double(c.order),
          double(scene.box_elements[0]),
          h,
          double(m.dof_count()),
          double(static_cast<int>(r.status)),
          double(r.iterations),
          double(r.restarts),
          r.true_relative_residual,
          m.l2_error().relative(),
          m.setup_seconds(),
          m.solve_seconds(),
          wall,
          cpu,
          c.frequency,
          2.0 * M_PI / c.wavenumber() / h * c.order,
          double(static_cast<int>(c.preconditioner)),
          m.preconditioner_seconds()};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Accuracy-cost sweep of the Helmholtz model (seed 002 paper 3)"};
  std::vector<std::string> wanted = {"cube", "duct", "duct_2khz"}, precisions = {"double", "float"};
  std::vector<int> orders = {1, 2, 3, 4}, elements_x;
  std::vector<std::string> preconditioners = {"jacobi"};
  std::string out = "out/accuracy_cost";
  double max_dofs = 8e5, float_tolerance = 1e-6;
  int threads = -1;
  app.add_option("--cases", wanted, "cases: cube, duct, duct_2khz")->delimiter(',')->capture_default_str();
  app.add_option("--orders", orders, "element orders")->delimiter(',')->check(CLI::Range(1, 4))->capture_default_str();
  app.add_option("--precision", precisions, "precisions: double,float")
      ->delimiter(',')
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  app.add_option("--max-dofs", max_dofs, "skip meshes with more DoFs")->capture_default_str();
  app.add_option("--float-tolerance", float_tolerance, "COCG tolerance of the float runs")->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--threads", threads, "OpenMP threads");
  app.add_option("--preconditioners", preconditioners, "COCG preconditioners: none, jacobi, chebyshev, pmg")
      ->delimiter(',')
      ->check(CLI::IsMember({"none", "jacobi", "chebyshev", "pmg"}))
      ->capture_default_str();
  app.add_option("--elements-x", elements_x, "only the meshes with these element counts along x")->delimiter(',');
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("sweep_helmholtz", [&] {
    pm::apps::KokkosSession kokkos(threads);
    pm::io::make_output_dir(out);
    for (const auto& w : wanted)
      if (std::none_of(cases().begin(), cases().end(), [&](const Case& c) { return c.name == w; }))
        throw std::invalid_argument("--cases: unknown case '" + w + "'; allowed: cube, duct, duct_2khz");
    for (const auto& cs : cases()) {
      if (std::find(wanted.begin(), wanted.end(), cs.name) == wanted.end()) continue;
      std::vector<Row> rows;
      auto write = [&] {
        const std::vector<std::string> header = {
            "is_float", "order", "elements_x", "h", "dofs", "status", "iterations", "restarts", "true_residual",
            "l2_error", "setup_seconds", "solve_seconds", "wall_seconds", "cpu_seconds", "frequency",
            "nodes_per_wavelength", "preconditioner", "preconditioner_seconds"};
        std::vector<std::vector<double>> cols(header.size());
        for (const auto& r : rows) {
          const double v[] = {r.is_float, r.order, r.elements_x, r.h, r.dofs, r.status, r.iterations, r.restarts,
                              r.true_residual, r.l2_error, r.setup, r.solve, r.wall, r.cpu, r.frequency,
                              r.nodes_per_wavelength, r.preconditioner, r.preconditioner_seconds};
          for (std::size_t k = 0; k < header.size(); ++k) cols[k].push_back(v[k]);
        }
        pm::io::write_csv(std::filesystem::path(out) / ("helmholtz_" + cs.name + ".csv"), header, cols);
      };
      for (const auto& prec : precisions)
        for (const int p : orders) {
          for (int nx : cs.elements.at(p)) {
            if (!elements_x.empty() && std::find(elements_x.begin(), elements_x.end(), nx) == elements_x.end()) continue;
            const std::array<int, 3> n = {nx, std::max(1, nx / cs.aspect[1]), std::max(1, nx / cs.aspect[2])};
            const double dofs = double(p * n[0] + 1) * (p * n[1] + 1) * (p * n[2] + 1);
            if (dofs > max_dofs) continue;
            for (const auto& pc : preconditioners) {
              pm::io::HelmholtzSceneOptions o;
              o.order = p;
              o.precision = prec;
              o.elements = n;
              auto scene = pm::io::load_helmholtz_scene(cs.scene, o);
              if (prec == "float") scene.config.solver.tolerance = float_tolerance;
              scene.config.preconditioner = pc == "none"        ? hz::Preconditioner::none
                                            : pc == "chebyshev" ? hz::Preconditioner::chebyshev
                                            : pc == "pmg"       ? hz::Preconditioner::pmg
                                                                : hz::Preconditioner::jacobi;
              rows.push_back(prec == "float" ? run_one<float>(scene) : run_one<double>(scene));
              const Row& r = rows.back();
              std::fprintf(stderr,
                           "[sweep] %s %s p = %d, %d x %d x %d elements, %.0f DoFs, %s: error %.3e, %d its (%s), %.2f s\n",
                           cs.name.c_str(), prec.c_str(), p, n[0], n[1], n[2], r.dofs, pc.c_str(), r.l2_error,
                           int(r.iterations), pm::solvers::to_string(static_cast<pm::solvers::SolveStatus>(int(r.status))),
                           r.wall);
              write();
            }
          }
        }
      std::printf("accuracy-cost table: %s/helmholtz_%s.csv\n", out.c_str(), cs.name.c_str());
    }
    return 0;
  });
}
