# The piezoelectric harvester's scenes and app (issue 35; included by tests/io/CMakeLists.txt): the loader's
# refusals and closed forms (test_piezo_scene), the app on each scene at a small size against the closed forms
# (check_piezo_harvester.py; label cli, like the other app runs), its exit code 2 for bad input, and a transient
# killed three times and restarted, bitwise equal to an uninterrupted run (tests/restart/kill_restart.py).
polymech_add_test(test_piezo_scene SOURCES test_piezo_scene.cpp LIBS polymech_io LABELS "io;scenes" THREADS 1)
set(piezo_env "OMP_NUM_THREADS=1;OMP_PROC_BIND=false;OMP_WAIT_POLICY=passive")
if(POLYMECH_SYSTEM_PYTHON)
  foreach(case IN ITEMS static strain harmonic transient partitioned)
    add_test(NAME piezo_harvester_${case}
      COMMAND ${POLYMECH_SYSTEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_piezo_harvester.py $<TARGET_FILE:piezo_harvester>
              ${case} ${CMAKE_CURRENT_BINARY_DIR}/piezo_${case} --source ${PROJECT_SOURCE_DIR})
    set_tests_properties(piezo_harvester_${case} PROPERTIES LABELS cli TIMEOUT 300 ENVIRONMENT "${piezo_env}"
      PASS_REGULAR_EXPRESSION "piezo_harvester ${case}: passed")
  endforeach()
  # the duToit transient at accuracy standard (8 960 steps, ~3 s on one core), checkpoints every 500 steps
  add_test(NAME restart_piezo_harvester
    COMMAND ${POLYMECH_SYSTEM_PYTHON} ${PROJECT_SOURCE_DIR}/tests/restart/kill_restart.py $<TARGET_FILE:piezo_harvester>
            ${CMAKE_CURRENT_BINARY_DIR}/restart_piezo --checkpoint-steps 500 -- --scene scenes/piezo/dutoit_harvester.toml
            --accuracy standard)
  set_tests_properties(restart_piezo_harvester PROPERTIES LABELS "restart;cli" TIMEOUT 600 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    PASS_REGULAR_EXPRESSION "results bitwise equal" ENVIRONMENT "${piezo_env}")
endif()
# bad input: exit code 2 and the key (or option) named
function(piezo_exit_code name scene pattern)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:piezo_harvester> -DSCENE=${scene} -DOUT=${CMAKE_CURRENT_BINARY_DIR}/never
            "-DARGS=${ARGN}" -P ${CMAKE_CURRENT_SOURCE_DIR}/exit_code.cmake)
  set_tests_properties(${name} PROPERTIES LABELS cli ENVIRONMENT "${piezo_env}" PASS_REGULAR_EXPRESSION "${pattern}")
endfunction()
piezo_exit_code(piezo_harvester_refuses_float ${PROJECT_SOURCE_DIR}/scenes/piezo/pvdf_bender.toml
  "exit code 2: piezo_harvester: error: .*pvdf_bender.toml:[0-9]+:[0-9]+: key 'model.precision' = \"float\" \\(--precision\\): .*allowed: \"double\""
  --precision float)
piezo_exit_code(piezo_harvester_refuses_steps_of_a_static_solve ${PROJECT_SOURCE_DIR}/scenes/piezo/pvdf_bender.toml
  "exit code 2: piezo_harvester: error: --steps 5: does not apply: a static analysis has no time steps" --steps 5)
piezo_exit_code(piezo_harvester_refuses_restart_of_a_sweep ${PROJECT_SOURCE_DIR}/tests/io/data/piezo_sweep_small.toml
  "exit code 2: piezo_harvester: error: --restart: a harmonic analysis has no checkpoints" --restart ${CMAKE_CURRENT_BINARY_DIR})
piezo_exit_code(piezo_harvester_names_a_bad_key ${CMAKE_CURRENT_SOURCE_DIR}/data/piezo_bad_electrode.toml
  "exit code 2: piezo_harvester: error: .*piezo_bad_electrode.toml:[0-9]+:1: key 'electrodes\\[1\\].kind' = \"floating\": surface \"interface 1\" touches the grounded conducting host")
