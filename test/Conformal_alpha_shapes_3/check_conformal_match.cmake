# Runs conformal_match (PROGRAM) in WORK_DIR: bad inputs and options must
# fail with status 1, one line "conformal_match: ..." and no output
# directory; crambin's surface (SURFACE) against itself must match every
# centre to itself, consistently, and write the three files; a PDB file
# (PDB) given twice must be sampled the same way twice.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(failures "")
set(out_dir ${WORK_DIR}/out)

# fails(NAME REGEX ARGS...): status 1, the message matching REGEX, no output directory
function(fails name regex)
  execute_process(COMMAND ${PROGRAM} --output ${out_dir} ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT result EQUAL 1)
    set(failures "${failures}\n${name}: status ${result}, expected 1: ${out}${err}" PARENT_SCOPE)
  elseif(NOT err MATCHES "^conformal_match: ${regex}[^\n]*\n$")
    set(failures "${failures}\n${name}: the message does not match '${regex}': ${err}" PARENT_SCOPE)
  elseif(EXISTS ${out_dir})
    set(failures "${failures}\n${name}: left an output directory" PARENT_SCOPE)
  endif()
endfunction()

file(WRITE ${WORK_DIR}/empty.xyz "")
file(WRITE ${WORK_DIR}/two.xyz "0 0 0\n1 0 0\n")
file(WRITE ${WORK_DIR}/bad.xyz "0 0 0\n1 0 x\n")
fails(missing "[^\n]*missing.xyz: no such file" ${WORK_DIR}/missing.xyz ${SURFACE})
fails(missing_b "[^\n]*missing.xyz: no such file" ${SURFACE} ${WORK_DIR}/missing.xyz)
fails(missing_pdb "[^\n]*missing.pdb: cannot be opened for reading" ${WORK_DIR}/missing.pdb ${SURFACE})
fails(empty "[^\n]*empty.xyz" ${WORK_DIR}/empty.xyz ${SURFACE})
fails(two_points "[^\n]*two.xyz: 2 points, a surface needs at least 3" ${WORK_DIR}/two.xyz ${SURFACE})
fails(not_a_number "[^\n]*bad.xyz" ${WORK_DIR}/bad.xyz ${SURFACE})
fails(one_file "expected two input files" ${SURFACE})
fails(unknown_option "unknown option --frobnicate" ${SURFACE} ${SURFACE} --frobnicate)
fails(centers_zero "--centers: must be an integer >= 1: '0'" ${SURFACE} ${SURFACE} --centers 0)
fails(centers_text "--centers: not a number: 'many'" ${SURFACE} ${SURFACE} --centers many)
fails(rings_decrease "--rings: the values must increase: '4,2'" ${SURFACE} ${SURFACE} --rings 4,2)
fails(radius_negative "--radius: must be > 0: '-1'" ${SURFACE} ${SURFACE} --radius -1)
fails(tolerance_nan "--tolerance: not a number: 'nan'" ${SURFACE} ${SURFACE} --tolerance nan)
fails(region_beyond "--region: 100000 is not a point of" ${SURFACE} ${SURFACE} --region 100000)
fails(chains_of_xyz "[^\n]*--chains-a and --chains-b are for PDB files" ${SURFACE} ${SURFACE} --chains-a A)
fails(pdb_no_chain "[^\n]*1crn.pdb: no atom kept in chain\\(s\\) 'Z'" ${PDB} ${SURFACE} --chains-a Z)
fails(value_missing "--top: needs a value" ${SURFACE} ${SURFACE} --top)

# crambin against itself: the centres' best candidates are themselves
execute_process(COMMAND ${PROGRAM} ${SURFACE} ${SURFACE} --radius 1.5,3 --centers 40 --candidates 400
                        --rings 2,4,6,8 --output ${out_dir}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  set(failures "${failures}\nself match: status ${result}: ${out}${err}")
elseif(NOT out MATCHES "consistent: 1.000 of the centres' best matches")
  set(failures "${failures}\nself match: not all consistent: ${out}")
else()
  file(STRINGS ${out_dir}/matches.csv rows)
  list(LENGTH rows count)
  list(GET rows 0 header)
  if(NOT count EQUAL 401 OR NOT header STREQUAL "a_index,a_x,a_y,a_z,rank,b_index,b_x,b_y,b_z,score,inlier")
    set(failures "${failures}\nmatches.csv: ${count} lines, header '${header}'")
  endif()
  foreach(row ${rows})
    # every rank 1 row: the centre itself, at distance 0, an inlier
    if(row MATCHES "^([0-9]+),[^,]*,[^,]*,[^,]*,1,([0-9]+),[^,]*,[^,]*,[^,]*,([^,]*),([01])$")
      if(NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2 OR NOT CMAKE_MATCH_3 STREQUAL "0" OR NOT CMAKE_MATCH_4 STREQUAL "1")
        set(failures "${failures}\nmatches.csv: a centre's best candidate is not itself: ${row}")
      endif()
    endif()
  endforeach()
  file(READ ${out_dir}/similarity.ply ply LIMIT 300)
  if(NOT ply MATCHES "element vertex 8142\n.*property float similarity\nend_header")
    set(failures "${failures}\nsimilarity.ply: header ${ply}")
  endif()
  if(NOT EXISTS ${out_dir}/summary.txt)
    set(failures "${failures}\nno summary.txt")
  endif()
endif()

# one PDB file given twice is sampled twice in one process: the same points
file(REMOVE_RECURSE ${out_dir})
execute_process(COMMAND ${PROGRAM} ${PDB} ${PDB} --radius 1.5 --centers 10 --candidates 50 --rings 2,4
                        --output ${out_dir}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  set(failures "${failures}\nPDB twice: status ${result}: ${out}${err}")
elseif(NOT out MATCHES "A: [^\n]*1crn.pdb, ([0-9]+) points")
  set(failures "${failures}\nPDB twice: no count of A's points: ${out}")
else()
  set(a_points ${CMAKE_MATCH_1})
  if(NOT out MATCHES "B: [^\n]*1crn.pdb, ${a_points} points")
    set(failures "${failures}\nPDB twice: A and B were sampled differently: ${out}")
  endif()
endif()

if(failures)
  message(FATAL_ERROR "conformal_match:${failures}")
endif()
