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
run(iron.pdb "${head}${N_LINE}\n${FE_LINE}\n" 1 "iron.pdb:3: no Bondi radius for element 'FE' \\(give a default radius\\)"
    --default-radius 0)
set(CA_ION_LINE "HETATM    6 CA    CA A 103      14.000  10.000  10.000  1.00 10.00              ")
run(calcium.pdb "${head}${N_LINE}\n${CA_ION_LINE}\n" 1 "calcium.pdb:3: no Bondi radius for element 'CA'"
    --default-radius 0)
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
run(iron_default.pdb "${head}${N_LINE}\n${FE_LINE}\n" 0
    "1 atom\\(s\\) without a Bondi radius given 2 A.*2 atoms; skin surface.*check passed" --check --spacing 0.3)

# odd inputs as files are written
# old files: the entry's code and a line number in columns 73-80, no element
set(OLD_N  "ATOM      1  N   PRO A   1      13.120  39.003   5.159  1.00 55.41      1HPV 186")
set(OLD_CA "ATOM      2  CA  PRO A   1      12.941  39.418   6.575  1.00 31.00      1HPV 187")
set(OLD_ZN "HETATM    3 ZN    ZN A 200      15.000  39.000   6.000  1.00 31.00      1HPV1704")
set(OLD_PE "HETATM    4  PE  AP5 A 215      11.000  39.000   6.000  1.00 25.81      1AKE1839")
run(old_columns.pdb "${head}${OLD_N}\n${OLD_CA}\n${OLD_ZN}\n${OLD_PE}\n" 0 "4 atoms; vdw surface.*check passed"
    --method vdw --check)
run(old_columns_no_hetatm.pdb "${head}${OLD_N}\n${OLD_CA}\n${OLD_ZN}\n" 0 "2 atoms; vdw surface.*check passed"
    --method vdw --check --no-hetatm)
string(REPLACE "1HPV 186" "1HPVx186" old_bad "${OLD_N}")
run(old_bad.pdb "${head}${old_bad}\n" 1 "old_bad.pdb:2: element symbol \\(columns 77-78\\) is not letters: 'x1'")
set(NO_NAME "ATOM      1  12  PRO A   1      13.120  39.003   5.159  1.00 55.41      1HPV 186")
run(no_element.pdb "${head}${NO_NAME}\n" 1
    "no_element.pdb:2: no element: columns 77-78 hold a line number and the atom name '12'")
# several models: the first unless asked; a missing model is an error
string(REPLACE "17.047" "47.047" far_n "${N_LINE}")
set(models "${head}MODEL        1\n${N_LINE}\n${CA_LINE}\nENDMDL\nMODEL        2\n${far_n}\nENDMDL\nEND\n")
run(models.pdb "${models}" 0 "2 atoms; vdw surface.*check passed" --method vdw --check)
run(model2.pdb "${models}" 0 "1 atoms; vdw surface.*check passed" --method vdw --check --model 2)
run(model3.pdb "${models}" 1 "model3.pdb: no model 3 \\(models in the file: 1, 2\\)" --model 3)
run(model_bad.pdb "${models}" 1 "--model: not a model serial number" --model 1.5)
# chains: selected; an absent chain is an error naming the chains there
string(REPLACE " A   1 " " B   2 " chain_b "${CA_LINE}")
run(chains.pdb "${head}${N_LINE}\n${chain_b}\n${FE_LINE}\n" 0 "1 atoms; vdw surface.*check passed"
    --method vdw --check --chains B)
run(chains_ab.pdb "${head}${N_LINE}\n${chain_b}\n" 0 "2 atoms; vdw surface" --method vdw --chains A,B)
run(chain_missing.pdb "${head}${N_LINE}\n${chain_b}\n" 1
    "chain_missing.pdb: no atom kept in chain\\(s\\) 'C' \\(chains in the file: A, B\\)" --chains C)
# alternate locations: per residue, the blank one and the first one seen
# (B in residue 2 although A came first in residue 1)
set(ALT_1A "ATOM      1  CB AGLU A   1      10.000  10.000  10.000  0.50  6.73           C  ")
set(ALT_1B "ATOM      2  CB BGLU A   1      10.500  10.000  10.000  0.50  6.73           C  ")
set(ALT_2B "ATOM      3  CB BGLU A   2      20.000  10.000  10.000  0.50  6.73           C  ")
set(ALT_2C "ATOM      4  CB CGLU A   2      20.500  10.000  10.000  0.50  6.73           C  ")
run(alternates.pdb "${head}${ALT_1A}\n${ALT_1B}\n${ALT_2B}\n${ALT_2C}\n${N_LINE}\n" 0
    "3 atoms; vdw surface.*check passed" --method vdw --check)

# pymol-data's structures as they are: every file of its demo and test
# folders that holds atoms must be read
set(pymol_files /usr/share/pymol/data/tut/1hpv.pdb /usr/share/pymol/data/demo/1tii.pdb
    /usr/share/pymol/data/demo/il2.pdb /usr/share/pymol/test/dat/3al1.pdb /usr/share/pymol/test/dat/odd01.pdb
    /usr/share/pymol/test/dat/odd02.pdb /usr/share/pymol/test/dat/names.pdb /usr/share/pymol/test/dat/small02.pdb)
foreach(f IN LISTS pymol_files)
  if(NOT EXISTS ${f})
    set(failures "${failures}\n${f} is missing: install pymol-data (apt-get install pymol-data)")
    continue()
  endif()
  get_filename_component(base ${f} NAME)
  execute_process(COMMAND ${PROGRAM} ${f} ${WORK_DIR}/pymol_${base}.xyz --method vdw --spacing 1.5
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0 OR NOT out MATCHES "atoms; vdw surface")
    set(failures "${failures}\n${f}: status ${result}: ${out}${err}")
  endif()
endforeach()
# 1HPV: chains A and B of the protease, 758 atoms each with the ligand
# (chain blank) left out; 1TII: chain D of five identical chains
set(chain_counts "tut/1hpv.pdb|A|758" "tut/1hpv.pdb|B|758" "demo/1tii.pdb|D|740")
foreach(c IN LISTS chain_counts)
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 file)
  list(GET c 1 chain)
  list(GET c 2 count)
  if(EXISTS /usr/share/pymol/data/${file})
    execute_process(COMMAND ${PROGRAM} /usr/share/pymol/data/${file} ${WORK_DIR}/chain_${chain}.xyz --method vdw
                            --spacing 1.5 --chains ${chain}
                    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT result EQUAL 0 OR NOT out MATCHES ": ${count} atoms; vdw surface")
      set(failures "${failures}\n${file} chain ${chain}: status ${result}, expected ${count} atoms: ${out}${err}")
    endif()
  endif()
endforeach()

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
