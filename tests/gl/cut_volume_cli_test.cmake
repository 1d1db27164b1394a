# Cut volumes as a user runs them (issue 45): each kind renders with --primaries none and is
# recorded in stats.json (kind, parameters, triangles) with the volume_cut pass in the plan; the
# same volumes from a JSON list give the same image, byte for byte, as on the command line.
file(MAKE_DIRECTORY ${OUT})
set(MODEL preset:zaphirus)
set(COMMON --size 160 120 --repeat 1 --warmup 0 --no-metrics --mean-filter 0 --ssao off)

# The model's bounds (inspect --json), whole units: the volumes sit in its middle.
execute_process(COMMAND ${CUTAWAY} inspect ${MODEL} --json RESULT_VARIABLE rc OUTPUT_VARIABLE report ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "inspect failed (${rc}): ${err}")
endif()
foreach(axis 0 1 2)
  string(JSON lo GET "${report}" bounds min ${axis})
  string(JSON hi GET "${report}" bounds max ${axis})
  string(REGEX REPLACE "\\..*" "" lo "${lo}")
  string(REGEX REPLACE "\\..*" "" hi "${hi}")
  math(EXPR span "${hi} - ${lo}")
  math(EXPR a${axis} "${lo} + ${span} / 3")
  math(EXPR b${axis} "${lo} + 2 * ${span} / 3")
  math(EXPR c${axis} "${lo} + ${span} / 2")
  math(EXPR top${axis} "${lo} - ${span}")   # above the model (z is depth)
endforeach()
math(EXPR radius "(${b0} - ${a0}) / 2")
set(BOX "box:${a0},${a1},${a2},${b0},${b1},${b2}")
set(CYLINDER "cylinder:${c0},${c1},${top2},${c0},${c1},${c2},${radius}")
# The box again as a closed OBJ mesh, corners in model coordinates.
file(WRITE ${OUT}/cube.obj "v ${a0} ${a1} ${a2}\nv ${b0} ${a1} ${a2}\nv ${b0} ${b1} ${a2}\nv ${a0} ${b1} ${a2}\n"
                           "v ${a0} ${a1} ${b2}\nv ${b0} ${a1} ${b2}\nv ${b0} ${b1} ${b2}\nv ${a0} ${b1} ${b2}\n"
                           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
set(MESH "mesh:${OUT}/cube.obj")

function(render name)
  execute_process(COMMAND ${CUTAWAY} render ${MODEL} ${COMMON} ${ARGN} --out ${OUT}/${name}.png
                          --stats ${OUT}/${name}.json --cell-ids ${OUT}/${name}_ids.png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/${name}.png)
    message(FATAL_ERROR "${name}: render failed (${rc}): ${err}")
  endif()
endfunction()

function(expect_volume name kind triangles)
  file(READ ${OUT}/${name}.json stats)
  string(JSON got GET "${stats}" configuration cut_volumes 0 kind)
  string(JSON count GET "${stats}" configuration cut_volumes 0 triangles)
  if(NOT got STREQUAL kind OR NOT count EQUAL triangles)
    message(FATAL_ERROR "${name}: stats record ${got} of ${count} triangles, expected ${kind} of ${triangles}")
  endif()
  string(JSON stage GET "${stats}" plan 0)
  if(NOT stage MATCHES "^cut_surface: clear_cut volume_cut")
    message(FATAL_ERROR "${name}: plan '${stage}', expected volume_cut without strategy_cut")
  endif()
endfunction()

render(box --primaries none --cut-volume ${BOX})
expect_volume(box box 12)
render(cylinder --primaries none --cut-volume ${CYLINDER})
expect_volume(cylinder cylinder 64)  # 16 sides: 32 wall triangles and 16 per cap
render(mesh --primaries none --cut-volume ${MESH})
expect_volume(mesh mesh 12)
# A box away from the model cuts nothing: the volumes above did cut.
render(outside --primaries none --cut-volume "box:${top0},${top1},${top2},${a0},${a1},${a2}")
file(SHA256 ${OUT}/outside_ids.png outside)
foreach(name box cylinder mesh)
  file(SHA256 ${OUT}/${name}_ids.png ids)
  if(ids STREQUAL outside)
    message(FATAL_ERROR "${name}: the same cell ids as with no cut")
  endif()
endforeach()
# The same volumes from a JSON list (mesh relative to the list's folder), with primaries cutting too.
file(WRITE ${OUT}/volumes.json "{\"volumes\": [
  {\"kind\": \"box\", \"min\": [${a0}, ${a1}, ${a2}], \"max\": [${b0}, ${b1}, ${b2}]},
  {\"kind\": \"cylinder\", \"from\": [${c0}, ${c1}, ${top2}], \"to\": [${c0}, ${c1}, ${c2}], \"radius\": ${radius}},
  {\"kind\": \"mesh\", \"file\": \"cube.obj\"}]}\n")
render(specs --cut-volume ${BOX} --cut-volume ${CYLINDER} --cut-volume ${MESH})
render(list --cut-volumes ${OUT}/volumes.json)
foreach(output .png _ids.png)
  file(SHA256 ${OUT}/specs${output} a)
  file(SHA256 ${OUT}/list${output} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "--cut-volumes gave another ${output} than the same --cut-volume specs")
  endif()
endforeach()
file(READ ${OUT}/list.json stats)
string(JSON stage GET "${stats}" plan 0)
if(NOT stage MATCHES "strategy_cut volume_cut")
  message(FATAL_ERROR "plan '${stage}': expected the primaries' cut, then the volumes'")
endif()
string(JSON volumes LENGTH "${stats}" configuration cut_volumes)
if(NOT volumes EQUAL 3)
  message(FATAL_ERROR "stats.json lists ${volumes} volumes, expected 3")
endif()
