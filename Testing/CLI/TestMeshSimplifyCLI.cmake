# meshsimplify end to end: a run that must succeed with valid JSON, and runs that must fail with
# a one-line message and a non-zero exit.

# meshsimplify with the given arguments, which must succeed; its standard output in `out`.
function (run_tool)
  execute_process(COMMAND "${TOOL}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE err)
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "meshsimplify ${ARGN} failed (${code}): ${err}")
  endif ()
  set(out "${output}" PARENT_SCOPE)
endfunction ()

run_tool(--method octree --reduction 0.9 --threads 2 --json "${INPUT}" "${OUTPUT}")
foreach (key IN ITEMS method input_triangles output_triangles time_ms threads max_error)
  string(JSON value ERROR_VARIABLE json_error GET "${out}" ${key})
  if (json_error)
    message(FATAL_ERROR "JSON lacks ${key}: ${out}")
  endif ()
endforeach ()
string(JSON input_triangles GET "${out}" input_triangles)
string(JSON output_triangles GET "${out}" output_triangles)
if (NOT input_triangles EQUAL 5804 OR output_triangles LESS 563 OR output_triangles GREATER 598)
  message(FATAL_ERROR "unexpected counts: ${out}")
endif ()
if (NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "no output file ${OUTPUT}")
endif ()

# --settings: each setting --set takes, with its default, range and line of help.
run_tool(--method volume --settings)
if (NOT out MATCHES "\nSurfaceErrorWeight=3000 \\[0, no bound\\]: Weight of the surface term" OR
    NOT out MATCHES "^PreserveBoundary=0 \\[0, 1\\]: Keep every point")
  message(FATAL_ERROR "--settings: ${out}")
endif ()

# The progressive method: one build for several levels, each written to its own file.
run_tool(--method progressive --levels 0.5,0.9 --json "${INPUT}" "${OUTPUT}.%l.ply")
string(JSON builds GET "${out}" builds)
string(JSON first GET "${out}" levels 0 output_triangles)
string(JSON second GET "${out}" levels 1 output_triangles)
string(JSON extract ERROR_VARIABLE json_error GET "${out}" levels 1 extract_ms)
if (NOT builds EQUAL 1 OR NOT first EQUAL 2902 OR NOT second EQUAL 580 OR json_error OR
    NOT EXISTS "${OUTPUT}.0.5.ply" OR NOT EXISTS "${OUTPUT}.0.9.ply")
  message(FATAL_ERROR "--levels: ${out}")
endif ()

# --morph: the cow towards its simplification, three frames written, one correspondence; at
# t = 0 the cow's triangles, with the paper's pairing at t = 1 about the coarse surface's.
run_tool(--method volume --reduction 0.95 "${INPUT}" "${OUTPUT}.coarse.ply")
run_tool(--morph --frames 3 --correspondence vertex --json "${INPUT}" "${OUTPUT}.coarse.ply" "${OUTPUT}.%f.ply")
string(JSON builds GET "${out}" builds)
string(JSON frames GET "${out}" frames)
string(JSON last GET "${out}" output_triangles)
if (NOT builds EQUAL 1 OR NOT frames EQUAL 3 OR last GREATER 400 OR NOT EXISTS "${OUTPUT}.0.ply" OR
    NOT EXISTS "${OUTPUT}.2.ply")
  message(FATAL_ERROR "--morph --frames: ${out}")
endif ()
run_tool(--morph --t 0 --json "${INPUT}" "${OUTPUT}.coarse.ply" "${OUTPUT}.morph.ply")
string(JSON first GET "${out}" output_triangles)
if (NOT first EQUAL 5804)
  message(FATAL_ERROR "--morph --t 0: ${out}")
endif ()

# --bake-texture: the terrain at 99 % with its elevation baked, as OBJ (with its .mtl naming the
# .png) and as glTF; then the same simplification given as a file with --original.
get_filename_component(data "${INPUT}" DIRECTORY)
run_tool(--method octree --reduction 0.99 --bake-texture 256 --json "${data}/jacksboro_dem_half.vtp" "${OUTPUT}.baked.obj")
string(JSON bake_ms GET "${out}" bake_ms)
string(JSON texture_size GET "${out}" texture_size)
get_filename_component(stem "${OUTPUT}" NAME)
file(READ "${OUTPUT}.baked.mtl" material)
if (NOT texture_size EQUAL 256 OR NOT bake_ms GREATER 0 OR NOT EXISTS "${OUTPUT}.baked.png" OR
    NOT material MATCHES "map_Kd ${stem}.baked.png")
  message(FATAL_ERROR "--bake-texture: ${out}, ${material}")
endif ()
run_tool(--method octree --reduction 0.99 --bake-texture 256 "${data}/jacksboro_dem_half.vtp" "${OUTPUT}.baked.glb")
run_tool(--method octree --reduction 0.99 --set GenerateOriginalIds=1 "${data}/jacksboro_dem_half.vtp" "${OUTPUT}.simplified.vtp")
run_tool(--bake-texture 256 --original "${data}/jacksboro_dem_half.vtp" --json "${OUTPUT}.simplified.vtp" "${OUTPUT}.rebaked.obj")
string(JSON method GET "${out}" method)
if (NOT method STREQUAL "bake" OR NOT EXISTS "${OUTPUT}.baked.glb" OR NOT EXISTS "${OUTPUT}.rebaked.png")
  message(FATAL_ERROR "--bake-texture --original: ${out}")
endif ()

# The volume method: counts within 1 %, its own error figure.
run_tool(--method volume --target-triangles 1000 --json "${INPUT}" "${OUTPUT}")
string(JSON output_triangles GET "${out}" output_triangles)
string(JSON square_volume_error GET "${out}" square_volume_error)
if (output_triangles LESS 990 OR output_triangles GREATER 1010 OR NOT square_volume_error GREATER 0)
  message(FATAL_ERROR "unexpected volume result: ${out}")
endif ()

# The parallel method: counts within 2 %, the same output with 1 and 2 threads, its rounds.
foreach (threads IN ITEMS 1 2)
  run_tool(--method parallel --reduction 0.9 --threads ${threads} --json "${INPUT}" "${OUTPUT}.${threads}.off")
  string(JSON output_triangles GET "${out}" output_triangles)
  string(JSON rounds GET "${out}" rounds)
  if (output_triangles LESS 568 OR output_triangles GREATER 592 OR NOT rounds GREATER 0)
    message(FATAL_ERROR "unexpected parallel result: ${out}")
  endif ()
endforeach ()
file(READ "${OUTPUT}.1.off" one)
file(READ "${OUTPUT}.2.off" two)
if (NOT one STREQUAL two)
  message(FATAL_ERROR "--method parallel: 1 and 2 threads wrote different meshes")
endif ()

# An error bound for the collapse methods: the largest distance reached, in the bound's units (a
# fraction of the bounding-box diagonal with --relative-error), within 1 %, and far fewer
# triangles; in input units without it (1 % of the cow's diagonal, 1.2171, is 0.012171).
foreach (method IN ITEMS volume parallel progressive)
  run_tool(--method ${method} --max-error 0.01 --relative-error --json "${INPUT}" "${OUTPUT}")
  string(JSON output_triangles GET "${out}" output_triangles)
  string(JSON max_error GET "${out}" max_error)
  if (output_triangles GREATER 2000 OR NOT max_error GREATER 0.005 OR max_error GREATER 0.01)
    message(FATAL_ERROR "unexpected ${method} result with a relative error bound: ${out}")
  endif ()
  run_tool(--method ${method} --max-error 0.012171 --json "${INPUT}" "${OUTPUT}")
  string(JSON max_error GET "${out}" max_error)
  if (NOT max_error GREATER 0.006 OR max_error GREATER 0.012171)
    message(FATAL_ERROR "unexpected ${method} result with an absolute error bound: ${out}")
  endif ()
endforeach ()

# Every JSON the tool prints parses: a 4 x 4 grid at 1e60 makes the volume error infinite,
# which is null, with a note.
set(grid "OFF\n25 32 0\n")
foreach (i RANGE 4)
  foreach (j RANGE 4)
    math(EXPR height "(${i} * ${j}) % 3")
    string(APPEND grid "${i}e60 ${j}e60 ${height}e60\n")
  endforeach ()
endforeach ()
foreach (i RANGE 3)
  foreach (j RANGE 3)
    math(EXPR a "${i} * 5 + ${j}")
    math(EXPR b "${a} + 1")
    math(EXPR c "${a} + 6")
    math(EXPR d "${a} + 5")
    string(APPEND grid "3 ${a} ${b} ${c}\n3 ${a} ${c} ${d}\n")
  endforeach ()
endforeach ()
file(WRITE "${OUTPUT}.huge.off" "${grid}")
run_tool(--method volume --json "${OUTPUT}.huge.off" "${OUTPUT}")
string(JSON type ERROR_VARIABLE json_error TYPE "${out}" square_volume_error)
string(JSON note ERROR_VARIABLE note_error GET "${out}" notes 0)
if (json_error OR note_error OR NOT type STREQUAL "NULL" OR NOT note STREQUAL "square_volume_error is inf")
  message(FATAL_ERROR "JSON with a value that is not finite: ${out}")
endif ()

# A reduction outside [0, 1] is clamped by every filter, with a warning: 1.5 asks for no triangle.
execute_process(COMMAND "${TOOL}" --method octree --reduction 1.5 --json "${INPUT}" "${OUTPUT}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(JSON output_triangles GET "${out}" output_triangles)
if (NOT code EQUAL 0 OR NOT output_triangles EQUAL 0 OR NOT err MATCHES "TargetReduction 1.5 is outside \\[0, 1\\]: 1 is used")
  message(FATAL_ERROR "--reduction 1.5: expected an empty mesh and a warning, got ${code}: ${out} ${err}")
endif ()

foreach (bad IN ITEMS "--method;nope;${INPUT};${OUTPUT}"
                      "--method;octree;--reduction;abc;${INPUT};${OUTPUT}"
                      "--method;octree;--reduction;nan;${INPUT};${OUTPUT}"
                      "--method;octree;/nonexistent/mesh.off;${OUTPUT}"
                      "--method;octree;${INPUT};${OUTPUT}.xyz"
                      "--method;octree;--set;Nope=1;${INPUT};${OUTPUT}"
                      "--method;volume;--max-error;-0.1;${INPUT};${OUTPUT}"
                      "--method;volume;--max-error;-1;${INPUT};${OUTPUT}"
                      "--method;octree;--target-triangles;-5;${INPUT};${OUTPUT}"
                      "--method;volume;--set;MaximumCellSize=1;${INPUT};${OUTPUT}"
                      "--method;parallel;--max-error;nan;${INPUT};${OUTPUT}"
                      "--method;parallel;--set;FeatureCurvature=1;${INPUT};${OUTPUT}"
                      "--method;volume;--levels;0.5;${INPUT};${OUTPUT}.%l.ply"
                      "--method;progressive;--levels;0.5;${INPUT};${OUTPUT}"
                      "--method;progressive;--levels;0.5,nan;${INPUT};${OUTPUT}.%l.ply"
                      "--method;progressive;--levels;0.5;--reduction;0.3;${INPUT};${OUTPUT}.%l.ply"
                      "--morph;--method;octree;${INPUT};${INPUT};${OUTPUT}"
                      "--morph;${INPUT};${OUTPUT}"
                      "--morph;--frames;3;${INPUT};${INPUT};${OUTPUT}"
                      "--morph;--t;2;${INPUT};${INPUT};${OUTPUT}"
                      "--morph;--correspondence;nope;${INPUT};${INPUT};${OUTPUT}"
                      "--morph;${INPUT};/nonexistent/coarse.off;${OUTPUT}"
                      "--frames;3;--method;octree;${INPUT};${OUTPUT}.%f.ply"
                      "--method;octree;--bake-texture;300;${INPUT};${OUTPUT}.obj"
                      "--method;octree;--bake-texture;128;${INPUT};${OUTPUT}.obj"
                      "--method;octree;--original;${INPUT};${INPUT};${OUTPUT}.obj"
                      "--method;octree;--bake-texture;256;--original;${INPUT};${INPUT};${OUTPUT}.obj"
                      "--method;octree;--bake-texture;256;${INPUT};${OUTPUT}.obj")
  execute_process(COMMAND "${TOOL}" ${bad} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (code EQUAL 0 OR NOT err MATCHES "^meshsimplify: ")
    message(FATAL_ERROR "expected a clean failure for '${bad}', got ${code}: ${err}")
  endif ()
endforeach ()
