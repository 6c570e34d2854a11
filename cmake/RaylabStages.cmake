# The stage contract in the build: every stage's functions are declared once in
# framework/include/raylab/stages/ and defined twice, in assignments/ and solutions/,
# with the same file names. A stage library holds one of the two definitions.

# The stage files, relative to assignments/ or solutions/. A new stage adds its file here.
set(RAYLAB_STAGE_FILES
  01_camera_rays/camera_rays.cpp
  02_sphere/sphere.cpp
  03_triangle/triangle.cpp
  03b_watertight/watertight.cpp
  04_box/box.cpp
  05_bvh/bvh.cpp
)

function(raylab_add_stage_library name root)
  set(sources "")
  foreach(file IN LISTS RAYLAB_STAGE_FILES)
    list(APPEND sources ${root}/${file})
  endforeach()
  # OBJECT, not STATIC: the framework calls the stage functions and the stages use the
  # framework, so the stage objects go straight into each program.
  add_library(${name} OBJECT ${sources})
  target_link_libraries(${name} PUBLIC raylab_framework PRIVATE raylab_options)
endfunction()

# raylab_add_program(NAME student|reference SOURCES...): one program linked with one variant.
function(raylab_add_program name variant)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE raylab_stages_${variant} raylab_framework raylab_options)
endfunction()
