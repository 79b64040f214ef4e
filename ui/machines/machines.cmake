# The operator station's machines: each machine's ui folder (form pages, 3D scene, plot
# channels, exports) and the registry (register_machine_uis.cpp). Adding a machine: its folder,
# its lines here, its line in register_machine_uis.cpp.
set(_m ${CMAKE_CURRENT_LIST_DIR})
set(CUTCELL_MACHINE_UI_SOURCES
  ${_m}/register_machine_uis.cpp
  ${_m}/pipe_robot/pipe_robot_ui.cpp
  ${_m}/pipe_robot/method_form.cpp
  ${_m}/pipe_robot/robot_dh_table_form.cpp
  ${_m}/pipe_robot/controller_form.cpp
  ${_m}/pipe_robot/method_comparison_page.cpp
  ${_m}/profile_cutter/profile_cutter_ui.cpp
  ${_m}/profile_cutter/profile_cutter_form.cpp
  ${_m}/quick_return/quick_return_ui.cpp
  ${_m}/quick_return/quick_return_form.cpp
  ${_m}/quick_return/quick_return_figures.cpp
  ${_m}/quick_return/quick_return_tracking_page.cpp
  ${_m}/flying_saw/flying_saw_ui.cpp
  ${_m}/flying_saw/flying_saw_forms.cpp
  ${_m}/flying_saw/flying_saw_figures.cpp
  ${_m}/section_steel/section_steel_ui.cpp
  ${_m}/section_steel/section_steel_form.cpp
  ${_m}/section_steel/section_steel_arms_form.cpp
)
# Scenes for the 3D view (plain data, built only with CutCell::view3d).
set(CUTCELL_MACHINE_UI_VIEW3D_SOURCES
  ${_m}/pipe_robot/pipe_robot_scene.cpp
  ${_m}/profile_cutter/profile_scene.cpp
  ${_m}/quick_return/quick_return_scene.cpp
  ${_m}/flying_saw/flying_saw_scene.cpp
  ${_m}/section_steel/section_steel_scene.cpp
)
