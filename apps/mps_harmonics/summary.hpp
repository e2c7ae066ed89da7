// The summary of apps/mps_harmonics (seed 000 §5.2): what the two runs and the analysis of
// models/mps_elastic/analysis.hpp give, as summary.json keys.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/case.hpp"
#include "io/mps_elastic_scene.hpp"
#include "mps_elastic/analysis.hpp"

namespace polymech::apps {

// The summary keys of a harmonics case (the scene, both runs, the ratios at the harmonics probe and at every
// probe, the normal reaction, the wall times and restarts) into j.
inline void put_harmonics_summary(nlohmann::json& j, const io::MpsElasticScene& scene, const mps_elastic::HarmonicsResult& res,
                                  int field) {
  namespace me = mps_elastic;
  const me::Config& c = scene.config;
  const auto& a = res.intact;
  const auto& b = res.crack;
  const bool analysed = res.analysis_error.empty();
  const std::string comp = scene.harmonics_component;
  j["spacing"] = c.spacing;
  j["dt"] = c.dt;
  j["steps"] = c.steps;
  j["particles"] = b.particles;
  j["bonds_crack"] = b.bonds;
  j["bonds_intact"] = a.bonds;
  j["crack_pairs"] = b.pairs;
  j["k_prime"] = c.crack.k_prime;
  j["drive_frequency"] = res.f0;
  j["probe"] = scene.harmonics_probe;
  j["component"] = comp;
  j["harmonics"] = {1, 2, 3, 4, 5};
  if (!analysed) j["analysis_error"] = res.analysis_error;
  j["ratios_crack"] = analysed ? nlohmann::json(res.ratios_crack) : nlohmann::json(nullptr);
  j["ratios_intact"] = analysed ? nlohmann::json(res.ratios_intact) : nlohmann::json(nullptr);
  j["ratios_method"] = me::ratios_method;
  j["window_start"] = analysed ? nlohmann::json(res.window_start) : nlohmann::json(nullptr);
  j["spectrum_ratios_crack"] = analysed ? nlohmann::json(res.spectrum_ratios_crack) : nlohmann::json(nullptr);
  j["spectrum_ratios_intact"] = analysed ? nlohmann::json(res.spectrum_ratios_intact) : nlohmann::json(nullptr);
  // the same ratios at every probe (how the harmonics fade with the distance from the crack)
  nlohmann::json per_probe = nlohmann::json::object();
  for (const auto& p : me::probe_ratios(res, field))
    per_probe[p.name] = p.measured ? nlohmann::json{{"ratios_crack", p.crack}, {"ratios_intact", p.intact}, {"window_start", p.window_start}}
                                   : nlohmann::json{{"note", p.note}};
  j["probes"] = per_probe;
  j["max_shear_force_intact"] = a.max_shear_force;
  j["normal_reaction"] = res.normal_reaction;
  j["normal_reaction_ratio"] = scene.normal_reaction_ratio;
  j["wall_seconds_intact"] = a.stats.wall_seconds;
  j["wall_seconds_crack"] = b.stats.wall_seconds;
  j["wall_seconds"] = a.stats.wall_seconds + b.stats.wall_seconds;
  j["restarts"] = a.stats.restarts + b.stats.restarts;
  put_subnormal_census(j, a.stats, "subnormal_census_intact");
  put_subnormal_census(j, b.stats, "subnormal_census_crack");
}

}  // namespace polymech::apps
