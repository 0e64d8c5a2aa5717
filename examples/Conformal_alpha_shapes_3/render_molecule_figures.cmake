# Renders the one surface that conformal_curvature wrote into FINE and into
# COARSE (whatever its name: surface_25pct_rings1.ply, or by radius) as
# FIG_DIR/1crn_fine.png and FIG_DIR/1crn_coarse.png, with RENDERER.
foreach(which FINE COARSE)
  file(GLOB surfaces ${${which}}/surface_*.ply)
  list(LENGTH surfaces count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one surface in ${${which}}, found ${count}")
  endif()
  string(TOLOWER ${which} name)
  execute_process(COMMAND ${RENDERER} ${surfaces} ${FIG_DIR}/1crn_${name}.png RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "render_surface_png failed on ${surfaces}")
  endif()
endforeach()
