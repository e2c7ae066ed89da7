// Element-free Galerkin cracked plates (seed 004, Hagihara et al.), static stage: an edge or centre crack
// in tension (a scene of scenes/efg/), solved with MLS shape functions; the J-integral on circles
// around the tip gives K_I, compared with the Tada, Paris & Irwin handbook value.
//   efg [--scene scenes/efg/edge_crack_static.toml] [--out out/efg] [--accuracy draft|standard|paper]
// Writes summary.json (nodes, gauss_points, handbook_factor, sif_static [[radius_m, K/(s sqrt(pi a))], ...],
// sif_error (mean over the paths), j_path_spread, crack_opening (at the crack centre or mouth), timings,
// shape_function_evaluations_per_second, wall_seconds), j_paths.csv and a snapshot efg.xdmf/.h5 of
// the displacement at the nodes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/app.hpp"
#include "efg/efg.hpp"
#include "io/efg_scene.hpp"

namespace pm = polymech;

int main(int argc, char** argv) {
  CLI::App app{"Element-free Galerkin cracked plate: static K_I from the J-integral against the handbook (seed 004)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/efg/edge_crack_static.toml", "out/efg");
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("efg", [&] {
    const auto scene = pm::io::load_efg_scene(opt.scene, opt.precision, opt.accuracy);
    if (pm::apps::announce_cost("efg", scene.header, scene.cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt.threads);
    pm::io::make_output_dir(opt.out);
    const auto t0 = std::chrono::steady_clock::now();
    pm::efg::Efg<double> model(scene.config);
    model.solve_static();
    const auto& c = scene.config;
    nlohmann::json j = pm::apps::summary_header("efg", scene.header);
    std::vector<double> radii, js, ks, fs, errs;
    nlohmann::json sif = nlohmann::json::array();
    double lo = 1e300, hi = -1e300;
    for (double r : c.j_radii) {
      const auto res = model.j_integral(r);
      radii.push_back(r);
      js.push_back(res.j);
      ks.push_back(res.k);
      fs.push_back(res.factor);
      errs.push_back(res.factor / scene.handbook - 1);
      sif.push_back({r, res.factor});
      lo = std::min(lo, res.j);
      hi = std::max(hi, res.j);
      if (!opt.quiet)
        std::printf("r = %.4g m: J = %.6g N/m, K_I = %.6g Pa m^0.5, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%)\n", r, res.j,
                    res.k, res.factor, scene.handbook, 100 * errs.back());
    }
    double mean = 0;
    for (double f : fs) mean += f;
    mean /= static_cast<double>(fs.size());
    const double cod = model.opening_at(c.crack == pm::efg::CrackKind::centre ? 0.0 : 0.0);
    // displacement at the nodes (MLS values: the nodal coefficients are not the displacements)
    const auto& nodes = model.layout().nodes;
    const auto v = model.fields_at(nodes, "node");
    pm::io::SnapshotMesh mesh;
    mesh.dim = 2;
    mesh.points = nodes;
    pm::io::SnapshotWriter snap(opt.out, "efg", mesh, true);
    pm::io::SnapshotField disp{"displacement", 2, {}};
    pm::io::SnapshotField sig{"stress", 3, {}};
    const auto& cf = model.config();
    const double nu = cf.poisson, mu = cf.young / (2 * (1 + nu));
    double lam = cf.young * nu / ((1 + nu) * (1 - 2 * nu));
    if (!cf.plane_strain) lam = 2 * lam * mu / (lam + 2 * mu);
    for (std::size_t i = 0; i < v.size() / 6; ++i) {
      const double* g = &v[6 * i];
      disp.values.insert(disp.values.end(), {g[0], g[1]});
      sig.values.insert(sig.values.end(), {(lam + 2 * mu) * g[2] + lam * g[5], lam * g[2] + (lam + 2 * mu) * g[5], mu * (g[3] + g[4])});
    }
    snap.add(0, 0.0, pm::io::Fields{disp, sig});
    snap.finish();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto& t = model.timings();
    j["nodes"] = model.nodes();
    j["gauss_points"] = model.layout().quad_count();
    j["crack"] = c.crack == pm::efg::CrackKind::edge ? "edge" : "centre";
    j["a_over_w"] = c.crack == pm::efg::CrackKind::edge ? c.crack_length / c.width : c.crack_length / (0.5 * c.width);
    j["state"] = c.plane_strain ? "plane_strain" : "plane_stress";
    j["handbook_factor"] = scene.handbook;
    j["sif_static"] = sif;
    j["sif_mean"] = mean;
    j["sif_error"] = mean / scene.handbook - 1;
    j["sif_max_abs_error"] = std::abs(*std::max_element(errs.begin(), errs.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }));
    j["j_path_spread"] = (hi - lo) / hi;
    j["crack_opening"] = cod;
    j["shape_seconds"] = t.shape_seconds;
    j["assembly_seconds"] = t.assembly_seconds;
    j["solve_seconds"] = t.solve_seconds;
    j["shape_function_points"] = t.evaluations;
    j["shape_function_values"] = t.entries;
    j["shape_function_evaluations_per_second"] = t.evaluations / t.shape_seconds;
    j["wall_seconds"] = wall;
    pm::io::write_json(opt.out / "summary.json", j);
    pm::io::write_csv(opt.out / "j_paths.csv", {"radius_m", "J_N_per_m", "K_Pa_sqrt_m", "K_factor", "handbook_factor_error"},
                      pm::io::Columns{radii, js, ks, fs, errs});
    std::printf("efg: %d nodes, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%), J path spread %.2f %%, %.2f s; results in %s\n",
                model.nodes(), mean, scene.handbook, 100 * (mean / scene.handbook - 1), 100 * (hi - lo) / hi, wall, opt.out.c_str());
    return 0;
  });
}
