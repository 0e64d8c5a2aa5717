# Runs molecular_surface_points (PROGRAM) on small PDB files written into
# WORK_DIR: malformed records must fail with status 1 and one line naming the
# file and the line; valid files must pass the program's own --check (points
# on their atom's sphere, outside all others, at the spacing).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# Columns: 13-16 atom name, 31-54 coordinates, 77-78 element.
set(N_LINE  "ATOM      1  N   THR A   1      17.047  14.099   3.625  1.00 13.79           N  ")
set(CA_LINE "ATOM      2  CA  THR A   1      16.967  12.784   4.338  1.00 10.80              ")
set(H_LINE  "ATOM      3  H   THR A   1      17.500  14.800   3.000  1.00 10.00           H  ")
set(W_LINE  "HETATM    4  O   HOH A 101      30.000  30.000  30.000  1.00 10.00           O  ")
set(FE_LINE "HETATM    5 FE   HEM A 102      12.000  10.000  10.000  1.00 10.00          FE  ")

set(failures "")

# run(NAME CONTENT EXPECTED_STATUS REGEX [ARGS...]): writes NAME, runs the
# program on it, checks the status and that the output matches REGEX.
function(run name content status regex)
  file(WRITE ${WORK_DIR}/${name} "${content}")
  execute_process(COMMAND ${PROGRAM} ${WORK_DIR}/${name} ${WORK_DIR}/${name}.xyz ${ARGN}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL status)
    set(failures "${failures}\n${name}: status ${result}, expected ${status}: ${out}${err}" PARENT_SCOPE)
  elseif(NOT "${out}${err}" MATCHES "${regex}")
    set(failures "${failures}\n${name}: output does not match '${regex}': ${out}${err}" PARENT_SCOPE)
  endif()
endfunction()

set(head "HEADER    TEST\r\n")

# malformed records: status 1, "molecular_surface_points: FILE:LINE: ..."
run(short.pdb "${head}${N_LINE}\r\nATOM      2  CA  THR A   1      16.967  12.784\r\n" 1
    "^molecular_surface_points: [^\n]*short.pdb:3: ATOM record too short: 46 characters, the coordinates need columns 31-54\n$")
string(REPLACE "17.047" "17.0a7" bad_x "${N_LINE}")
run(not_a_number.pdb "${head}${bad_x}\n" 1
    "not_a_number.pdb:2: x coordinate \\(columns 31-38\\): not a number: '17.0a7'")
string(REPLACE "14.099" "      " blank_y "${N_LINE}")
run(blank.pdb "${head}${blank_y}\n" 1 "blank.pdb:2: y coordinate \\(columns 39-46\\) is blank")
string(REPLACE "           N  " "          N1  " bad_element "${N_LINE}")
run(element.pdb "${head}${bad_element}\n" 1 "element.pdb:2: element symbol \\(columns 77-78\\) is not letters: 'N1'")
run(iron.pdb "${head}${N_LINE}\n${FE_LINE}\n" 1 "iron.pdb:3: no Bondi radius for element 'FE' \\(give a default radius\\)")
set(CA_ION_LINE "HETATM    6 CA    CA A 103      14.000  10.000  10.000  1.00 10.00              ")
run(calcium.pdb "${head}${N_LINE}\n${CA_ION_LINE}\n" 1 "calcium.pdb:3: no Bondi radius for element 'CA'")
run(empty.pdb "${head}REMARK nothing\n" 1 "empty.pdb: no ATOM or HETATM record")
run(only_water.pdb "${head}${W_LINE}\n" 1 "only_water.pdb: every atom was left out")
execute_process(COMMAND ${PROGRAM} ${WORK_DIR}/missing.pdb RESULT_VARIABLE result ERROR_VARIABLE err)
if(NOT result EQUAL 1 OR NOT err MATCHES "missing.pdb: cannot be opened for reading")
  set(failures "${failures}\nmissing.pdb: status ${result}: ${err}")
endif()

# valid files: the element from the atom name (" CA " is carbon), hydrogens
# and waters left out unless asked, the default radius for iron
run(two_atoms.pdb "${head}${N_LINE}\r\n${CA_LINE}\r\n${H_LINE}\r\n${W_LINE}\r\nEND\r\n" 0
    "2 atoms; vdw surface.*check passed" --method vdw --check --normals)
run(with_h.pdb "${head}${N_LINE}\n${CA_LINE}\n${H_LINE}\n${W_LINE}\n" 0
    "4 atoms; sas surface.*check passed" --method sas --hydrogens --water --check)
run(iron_default.pdb "${head}${N_LINE}\n${FE_LINE}\n" 0 "2 atoms; skin surface.*check passed"
    --default-radius 2.0 --check --spacing 0.3)

# the count of the two-atom vdW sample: the two spheres (N 1.55, C 1.70, 1.47
# apart) cover about 44 A^2; at spacing 0.4 a maximal Poisson-disk sample
# holds one point per 0.14 to 0.4 A^2
set(lines "")
if(EXISTS ${WORK_DIR}/two_atoms.pdb.xyz)
  file(STRINGS ${WORK_DIR}/two_atoms.pdb.xyz lines)
endif()
list(LENGTH lines count)
if(count LESS 110 OR count GREATER 320)
  set(failures "${failures}\ntwo_atoms.pdb.xyz: ${count} points")
endif()
set(first "")
if(count GREATER 0)
  list(GET lines 0 first)
endif()
if(NOT first MATCHES "^-?[0-9.]+ -?[0-9.]+ -?[0-9.]+ -?[0-9.]+ -?[0-9.]+ -?[0-9.]+$")
  set(failures "${failures}\ntwo_atoms.pdb.xyz: not 6 columns: ${first}")
endif()

if(NOT failures STREQUAL "")
  message(FATAL_ERROR "molecular_surface_points:${failures}")
endif()
