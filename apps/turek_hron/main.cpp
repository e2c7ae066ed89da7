// The Turek-Hron CFD tests (issue 36; seed 002 paper 1 eqs. (1)-(3) on a fixed mesh): the channel with the
// cylinder and the rigid flag, Taylor-Hood Q2/Q1 (models/flow), run as the scene says (io/flow_scene.hpp; the cases
// in apps/turek_hron/cfd.cpp and fsi1.cpp, their analysis in models/flow/analysis.hpp and turek_hron.hpp):
//   cfd1, cfd2 -> steady Newton (Oseen steps first): summary.json with drag and lift (drag_mean = the drag,
//                 the amplitudes 0) against Turek & Hron 2006's reference, Newton iterations, CPU seconds;
//   cfd3       -> BDF2 from rest with the inflow ramped: forces.csv (t, drag, lift, Newton iterations, written
//                 as the run goes), summary.json with drag_mean, drag_amplitude, lift_mean, lift_amplitude
//                 and frequency over the last lift period as the benchmark defines them (periodic: false and
//                 the last values when no shedding was found), the previous period's values (how settled the
//                 oscillation is), CPU seconds and the cost split;
//   fsi1       -> the elastic flag, partitioned steady coupling (apps/turek_hron/fsi1.cpp): summary.json with
//                 ux_A, uy_A, drag, lift against Table 12, the coupling's evaluations, CPU split;
//   fsi2, fsi3 -> the elastic flag in time, strongly coupled per step (apps/turek_hron/fsi_transient.cpp):
//                 series.csv (t, drag, lift, ux, uy of A, coupling evaluations), summary.json with the means and
//                 amplitudes over the last period of uy(A) and its frequency against Table 13, `reason` and exit
//                 code 1 when the coupling stops;
//   flap       -> the weakly coupled check (CSM3's flag under gravity in the fluid at rest), the same loop:
//                 summary.json's "flap" keys, the period of uy(A) against the same flag's in vacuo.
//   harvester  -> the flow-driven piezoelectric harvester (seed 002 paper 1 case 2, [case] benchmark = "harvester";
//                 apps/turek_hron/harvester.cpp): series.csv (t, tip, drag, lift, voltage, power, ...), summary.json
//                 with the statistics over the last window against the plate's first frequency, `reason` and exit
//                 code 1 when the coupling stops.
//   turek_hron [--scene scenes/flow/cfd1.toml] [--out out/turek_hron] [--accuracy draft|standard|paper]
//              [--steps N] [--dry-run] [--threads 1]
//              [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]   (the time-dependent cfd3, fsi2, fsi3)
#include <stdexcept>
#include <string>

#include "apps/common/app.hpp"
#include "apps/turek_hron/cases.hpp"
#include "io/flow_scene.hpp"

namespace pm = polymech;

int main(int argc, char** argv) {
  CLI::App app{"The Turek-Hron CFD and FSI tests: steady CFD1, CFD2 and periodic CFD3 past the cylinder and rigid flag, "
               "steady FSI1 and periodic FSI2, FSI3 with the elastic flag, the flow-driven piezoelectric harvester (Taylor-Hood Navier-Stokes, "
               "partitioned coupling, issue 36)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/flow/cfd1.toml", "out/turek_hron");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "turek_hron", argc, argv)) return *rc;
  return pm::apps::guarded("turek_hron", [&] {
    const auto scene = pm::io::load_flow_scene(opt.scene, {opt.accuracy, opt.precision});
    const bool transient = scene.config.transient;
    if (!transient && opt.steps > 0)
      throw std::invalid_argument("--steps " + std::to_string(opt.steps) + ": does not apply: a steady test (cfd1, cfd2, fsi1) has no time steps");
    if (!transient && !ropt.restart.empty())
      throw std::invalid_argument("--restart: " + opt.scene.string() + " is a steady test (cfd1, cfd2, fsi1: one solve, nothing to resume)");
    const auto cost = transient ? pm::apps::with_steps(scene.cost, scene.config.steps(), opt.steps) : scene.cost;
    if (pm::apps::announce_cost("turek_hron", scene.header, cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    if (scene.config.harvester) return pm::apps::run_flow_harvester(scene, opt, ropt);
    if (scene.config.fsi)
      return transient ? pm::apps::run_turek_hron_fsi_transient(scene, opt, ropt) : pm::apps::run_turek_hron_fsi1(scene, opt);
    return transient ? pm::apps::run_turek_hron_transient(scene, opt, ropt) : pm::apps::run_turek_hron_steady(scene, opt);
  });
}
