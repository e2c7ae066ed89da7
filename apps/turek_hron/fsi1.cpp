// The Turek-Hron FSI1 case (issue 36; Turek & Hron 2006, section 3.3, Table 12): the coupled steady state of the
// channel flow at Ubar = 0.2 and the elastic SVK flag, partitioned Dirichlet-Neumann (models/fsi/turek_hron_fsi.hpp:
// the fluid on the pseudo-elastically moved mesh, the solid under the fluid's nodal forces, IQN-ILS / Aitken /
// relaxation on the wet nodes' displacement, models/fsi/coupling.hpp).
#include "apps/turek_hron/cases.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <string>

#include "apps/common/case.hpp"
#include "common/host_copy.hpp"
#include "fsi/turek_hron_fsi.hpp"

namespace polymech::apps {

int run_turek_hron_fsi1(const io::FlowScene& scene, const CommonOptions& opt) {
  const auto& s = scene.config;
  CaseSpec spec("turek_hron", scene.header, 0);
  spec.checkpoints = false;
  spec.progress = false;
  Case cs(spec, opt, {});
  const std::clock_t c0 = std::clock();
  const auto w0 = std::chrono::steady_clock::now();
  fsi::TurekHronFsiCase c;
  c.level = s.level;
  c.mean_velocity = s.mean_velocity;
  c.rho_f = s.density;
  c.nu_f = s.viscosity;
  c.coupling.method = fsi::coupling_method(s.coupling_method);
  c.coupling.tolerance = s.coupling_tolerance;
  c.coupling.max_iterations = s.coupling_max_iterations;
  c.coupling.omega = s.coupling_omega;
  c.coupling.reuse = s.coupling_reuse;
  fsi::TurekHronFsi model(c);
  if (!opt.quiet)
    std::fprintf(stderr, "[turek_hron] %s\n  FSI1, level %d: %lld fluid unknowns, %lld mesh-motion unknowns, %lld solid DoFs, %zu wet "
                 "nodes; %s coupling to %g; %s\n", scene.header.title.c_str(), s.level, static_cast<long long>(model.fluid_unknowns()),
                 static_cast<long long>(model.mesh_unknowns()), static_cast<long long>(model.solid_unknowns()), model.interface_nodes(),
                 s.coupling_method.c_str(), s.coupling_tolerance, thread_count().c_str());
  fsi::TurekHronFsiResult r;
  std::string reason;
  try {
    r = model.solve_steady();
    if (!r.coupling.converged) reason = "the " + s.coupling_method + " coupling stopped: " + r.coupling.reason;
  } catch (const std::runtime_error& e) {  // a fluid or solid Newton iteration inside the coupling failed
    reason = e.what();
    r.coupling.converged = false;
  }
  const bool converged = reason.empty();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const auto ref = fsi::turek_hron_fsi1_reference();
  const auto& t = model.timings();
  nlohmann::json j = cs.summary();
  j["test"] = "fsi1";
  j["analysis"] = "steady";
  put_fsi_sizes(j, model, s.level);
  j["converged"] = converged;
  if (!converged) j["reason"] = reason;
  j["ux_A"] = r.ux;
  j["uy_A"] = r.uy;
  put_steady_force(j, "drag", r.drag, ref.drag);
  put_steady_force(j, "lift", r.lift, ref.lift);
  // the keys (a steady state: the means are the values, the amplitudes 0)
  j["ux_mean"] = r.ux;
  j["ux_amplitude"] = 0.0;
  j["uy_mean"] = r.uy;
  j["uy_amplitude"] = 0.0;
  j["ux_A_error"] = r.ux / ref.ux - 1.0;
  j["uy_A_error"] = r.uy / ref.uy - 1.0;
  j["flag_drag"] = r.flag_drag;
  j["flag_lift"] = r.flag_lift;
  j["min_jacobian_ratio"] = r.min_jacobian_ratio;
  j["interface_mismatch"] = r.interface_mismatch;
  j["coupling"] = {{"method", s.coupling_method}, {"evaluations", r.coupling.iterations}, {"converged", r.coupling.converged},
                   {"residual", r.coupling.residual}, {"tolerance", s.coupling_tolerance}, {"history", r.coupling.history}};
  j["coupling_evaluations"] = t.evaluations;
  j["coupling_method"] = s.coupling_method;
  j["fluid_newton_iterations"] = t.fluid_newton;
  j["solid_newton_iterations"] = t.solid_newton;
  j["cpu_seconds"] = cpu;
  j["wall_seconds"] = wall;
  j["cpu_split"] = {{"setup", t.setup}, {"mesh_motion", t.mesh}, {"fluid", t.fluid}, {"solid", t.solid}};
  j["fluid_split"] = flow_cpu_split(model.fluid().timings());
  j["reference"] = {{"source", "Turek & Hron 2006, Table 12"}, {"ux_A", ref.ux}, {"uy_A", ref.uy}, {"drag", ref.drag}, {"lift", ref.lift}};
  if (!(s.mean_velocity == 0.2 && s.density == 1000.0 && s.viscosity == 1e-3))
    j["reference"]["note"] = "the scene changes the benchmark's inflow, density or viscosity";
  const int rc = cs.finish(j, {"summary.json"});
  std::printf("turek_hron: FSI1 level %d, %lld fluid unknowns: ux(A) %.5e (%+.2f %%), uy(A) %.5e (%+.2f %%), drag %.5f (%+.3f %%), "
              "lift %.5f (%+.3f %%); %d %s evaluations%s, CPU %.2f s; results in %s\n", s.level,
              static_cast<long long>(model.fluid_unknowns()), r.ux, 100 * (r.ux / ref.ux - 1), r.uy, 100 * (r.uy / ref.uy - 1), r.drag,
              100 * (r.drag / ref.drag - 1), r.lift, 100 * (r.lift / ref.lift - 1), t.evaluations, s.coupling_method.c_str(),
              converged ? "" : " (NOT converged)", cpu, cs.out().c_str());
  if (!converged) {
    std::fprintf(stderr, "turek_hron: %s\n", reason.c_str());
    return 1;
  }
  return rc;
}

}  // namespace polymech::apps
