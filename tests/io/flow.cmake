# The Turek-Hron app (issue 36; included by tests/io/CMakeLists.txt): a misspelt key stops it with exit code 2
# naming the file, line and key; CFD1 at accuracy draft (level 1, ~1 s) writes summary.json with drag and lift
# within 0.3 % / 0.5 % of the reference (the digits below); CFD3 at draft for 5 steps writes forces.csv and a
# summary that says it is not periodic yet. FSI1 (the elastic flag): a misspelt [coupling] key exits 2 with file:line:key;
# at accuracy draft (level 1, ~3 s) converged with ux(A), uy(A), drag, lift near Table 12 (the patterns below:
# measured -1.04, -0.39, -0.28, +0.31 %; the digits allow ux 2.2-2.3e-5 (-3..+1 %), uy 7.9-8.4e-4 (-3.8..+2.3 %),
# drag 14.22-14.30, lift 0.75-0.77); a coupling cut short (2 evaluations) writes the reason and exits 1.
# FSI2 (the elastic flag in time): a misspelt [time] key exits 2 with file:line:key; 5 steps at accuracy draft (level 0,
# dt 0.008, ~1 s) write series.csv and a summary whose issue keys (drag, lift, ux, uy: mean and amplitude;
# frequency) are numbers (a NaN would be written null), not periodic yet; a coupling cut to 1 evaluation per step
# writes the reason and exits 1.
# The weakly coupled flap (CSM3's flag in the fluid at rest, rho_f 1): 60 steps at accuracy draft (level 0, dt 0.01,
# ~3 s) reach the first minimum of uy(A) (-0.1271 measured) with a period within 2 % of the in-vacuo one (x 1.0069).
# Label cli, like the other app runs.
set(flow_env "OMP_NUM_THREADS=1;OMP_PROC_BIND=false;OMP_WAIT_POLICY=passive")
function(flow_app_test name scene pattern)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:turek_hron> -DSCENE=${scene} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/${name}
            -DSHOW=summary.json "-DARGS=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/exit_code.cmake)
  set_tests_properties(${name} PROPERTIES LABELS cli TIMEOUT 120 ENVIRONMENT "${flow_env}" PASS_REGULAR_EXPRESSION "${pattern}")
endfunction()
flow_app_test(turek_hron_names_a_bad_key ${CMAKE_CURRENT_SOURCE_DIR}/data/flow_bad_key.toml
  "exit code 2: turek_hron: error: .*flow_bad_key.toml:[0-9]+:1: unknown key 'solver.tolerence'; allowed in \\[solver\\]: .*tolerance.*summary.json: missing")
flow_app_test(turek_hron_cfd1_draft ${PROJECT_SOURCE_DIR}/scenes/flow/cfd1.toml
  "exit code 0: .*summary.json: .*\"drag_mean\": 14\\.25[0-9]*,.*\"level\": 1,.*\"lift_mean\": 1\\.11[0-9]*,"
  --accuracy draft)
flow_app_test(turek_hron_cfd3_steps ${PROJECT_SOURCE_DIR}/scenes/flow/cfd3.toml
  "exit code 0: .*summary.json: .*\"files\": \\[[^]]*\"forces.csv\".*\"periodic\": false,.*\"steps\": 5,"
  --accuracy draft --steps 5)
flow_app_test(turek_hron_fsi1_names_a_bad_coupling_key ${CMAKE_CURRENT_SOURCE_DIR}/data/fsi1_bad_coupling_key.toml
  "exit code 2: turek_hron: error: .*fsi1_bad_coupling_key.toml:[0-9]+:1: unknown key 'coupling.max_iteration'; allowed in \\[coupling\\]: .*max_iterations.*summary.json: missing")
flow_app_test(turek_hron_fsi1_draft ${PROJECT_SOURCE_DIR}/scenes/flow/fsi1.toml
  "exit code 0: .*summary.json: .*\"converged\": true,.*\"coupling_evaluations\": [4-8],.*\"drag\": 14\\.(2[2-9]|30)[0-9]*,.*\"level\": 1,.*\"lift\": 0\\.7[5-6][0-9]*,.*\"test\": \"fsi1\",.*\"ux_A\": 2\\.2[0-9]*e-05,.*\"uy_A\": 0\\.000(79|8[0-3])[0-9]*,"
  --accuracy draft)
flow_app_test(turek_hron_fsi1_coupling_stops ${CMAKE_CURRENT_SOURCE_DIR}/data/fsi1_coupling_stops.toml
  "exit code 1: .*the aitken coupling stopped: no convergence in 2 evaluations.*summary.json: .*\"converged\": false,.*\"reason\": \"the aitken coupling stopped: no convergence in 2 evaluations")
flow_app_test(turek_hron_fsi2_names_a_bad_key ${CMAKE_CURRENT_SOURCE_DIR}/data/fsi2_bad_key.toml
  "exit code 2: turek_hron: error: .*fsi2_bad_key.toml:[0-9]+:1: unknown key 'time.ramp_tme'; allowed in \\[time\\]: .*ramp_time.*summary.json: missing")
set(flow_num "-?[0-9][0-9.e+-]*,")
flow_app_test(turek_hron_fsi2_steps ${PROJECT_SOURCE_DIR}/scenes/flow/fsi2.toml
  "exit code 0: .*summary.json: .*\"converged\": true,.*\"coupling_evaluations_per_step\": [1-9][0-9.]*,.*\"drag_amplitude\": ${flow_num}.*\"drag_mean\": ${flow_num}.*\"files\": \\[[^]]*\"series.csv\".*\"frequency\": 0\\.0,.*\"level\": 0,.*\"lift_amplitude\": ${flow_num}.*\"lift_mean\": ${flow_num}.*\"periodic\": false,.*\"reference\": .*\"steps\": 5,.*\"test\": \"fsi2\",.*\"ux_amplitude\": ${flow_num}.*\"ux_mean\": ${flow_num}.*\"uy_amplitude\": ${flow_num}.*\"uy_mean\": -?[0-9]"
  --accuracy draft --steps 5)
flow_app_test(turek_hron_fsi2_coupling_stops ${CMAKE_CURRENT_SOURCE_DIR}/data/fsi2_coupling_stops.toml
  "exit code 1: .*step 1: .*the coupling did not converge.*summary.json: .*\"converged\": false,.*\"reason\": \"step 1: turek-hron fsi transient: the coupling did not converge")
flow_app_test(turek_hron_flap_steps ${PROJECT_SOURCE_DIR}/scenes/flow/flap.toml
  "exit code 0: .*summary.json: .*\"converged\": true,.*\"first_min_uy\": -0\\.12[0-9]*,.*\"period_ratio\": 1\\.0(0[1-9]|1[0-9])[0-9]*,.*\"test\": \"flap\""
  --accuracy draft --steps 60)
# The flow-driven harvester (seed 002 paper 1 case 2, [case] benchmark = "harvester"; apps/turek_hron/harvester.cpp):
# a misspelt [case] key, a negative cylinder side and an unknown scheme exit 2 naming file:line:key and what is
# allowed; 20 steps at level 0 with the nested (partitioned) loop (~0.5 s) write series.csv and a summary whose
# keys are numbers (the run shorter than its window: the note says so); a coupling cut to one evaluation per step
# writes the reason and exits 1.
flow_app_test(turek_hron_harvester_names_a_bad_key ${CMAKE_CURRENT_SOURCE_DIR}/data/harvester_bad_key.toml
  "exit code 2: turek_hron: error: .*harvester_bad_key.toml:11:1: unknown key 'case.plate_lenght'; allowed in \\[case\\]: .*plate_length.*summary.json: missing")
flow_app_test(turek_hron_harvester_negative_side ${CMAKE_CURRENT_SOURCE_DIR}/data/harvester_negative_side.toml
  "exit code 2: turek_hron: error: .*harvester_negative_side.toml:11:1: key 'case.side' = -0.03 is out of range: must be in \\[0, 10\\] m.*lock-in side.*summary.json: missing")
flow_app_test(turek_hron_harvester_bad_scheme ${CMAKE_CURRENT_SOURCE_DIR}/data/harvester_bad_scheme.toml
  "exit code 2: turek_hron: error: .*harvester_bad_scheme.toml:11:1: key 'case.scheme' = \"nested\" is not allowed; allowed: \"monolithic\", \"partitioned\".*summary.json: missing")
flow_app_test(turek_hron_harvester_steps ${CMAKE_CURRENT_SOURCE_DIR}/data/harvester_partitioned.toml
  "exit code 0: .*summary.json: .*\"cells\": 278,.*\"circuit_solves_per_step\": [1-9][0-9.]*,.*\"converged\": true,.*\"coupling_evaluations_per_step\": [1-9][0-9.]*,.*\"drag_amplitude\": ${flow_num}.*\"drag_mean\": ${flow_num}.*\"f1_sc_Hz\": 3\\.7[0-9]*,.*\"files\": \\[[^]]*\"series.csv\".*\"level\": 0,.*\"lift_amplitude\": ${flow_num}.*\"lift_frequency\": ${flow_num}.*\"power_mean\": ${flow_num}.*\"scheme\": \"partitioned\",.*\"steps\": 20,.*\"test\": \"harvester\",.*\"tip_amplitude\": ${flow_num}.*\"tip_frequency\": ${flow_num}.*\"voltage_amplitude\": ${flow_num}"
  --steps 20)
flow_app_test(turek_hron_harvester_coupling_stops ${CMAKE_CURRENT_SOURCE_DIR}/data/harvester_coupling_stops.toml
  "exit code 1: .*step 1: .*the coupling did not converge.*summary.json: .*\"converged\": false,.*\"reason\": \"step 1: flow harvester: the coupling did not converge")
