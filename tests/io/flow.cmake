# The Turek-Hron app (issue 36; included by tests/io/CMakeLists.txt): a misspelt key stops it with exit code 2
# naming the file, line and key; CFD1 at accuracy draft (level 1, ~1 s) writes summary.json with drag and lift
# within 0.3 % / 0.5 % of the reference (the digits below); CFD3 at draft for 5 steps writes forces.csv and a
# summary that says it is not periodic yet. Label cli, like the other app runs.
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
