# The simulated rig of each machine (app/gui/machines/<id>/) and their list (sim_rigs.cpp).
set(CUTCELL_MACHINE_RIG_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/sim_rigs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pipe_robot_6axis/sim_rig.cpp
  ${CMAKE_CURRENT_LIST_DIR}/profile_cutter_2axis/sim_rig.cpp
)
