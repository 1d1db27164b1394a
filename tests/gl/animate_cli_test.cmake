# `cutaway animate` as a user runs it (issue 44): an H.264 MP4 that ffprobe reads with the expected
# frame count, stats.json with one entry per frame, smooth coherence against none on petra's SWAT
# flood, and the bad-input answers (one line, exit 2, nothing written).
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(PETRA preset:petra --property SWAT --range 0.5 1 --size 160 120)

function(ffprobe_field file field result)
  execute_process(COMMAND ffprobe -v error -select_streams v:0 -count_frames -show_entries stream=${field}
                          -of default=noprint_wrappers=1:nokey=1 ${file}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE value OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ffprobe ${file}: exit ${rc}")
  endif()
  set(${result} "${value}" PARENT_SCOPE)
endfunction()

# Steps 1..3 at 3 frames per step: (3 - 1) x 3 + 1 = 7 frames, also written as PNG, the camera
# turning 30 degrees over them.
execute_process(COMMAND ${CUTAWAY} animate ${PETRA} --steps 1 3 --frames-per-step 3 --orbit 30 --out ${OUT}/short.mp4
                        --stats ${OUT}/short.json --frames ${OUT}/frames
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/short.mp4)
  message(FATAL_ERROR "animate failed (${rc}): ${err}")
endif()
ffprobe_field(${OUT}/short.mp4 codec_name codec)
ffprobe_field(${OUT}/short.mp4 pix_fmt pixel_format)
ffprobe_field(${OUT}/short.mp4 nb_read_frames frames)
if(NOT codec STREQUAL "h264" OR NOT pixel_format STREQUAL "yuv420p" OR NOT frames EQUAL 7)
  message(FATAL_ERROR "short.mp4: ${codec} ${pixel_format} with ${frames} frames, expected h264 yuv420p with 7")
endif()
file(GLOB pngs ${OUT}/frames/frame_*.png)
list(LENGTH pngs png_count)
if(NOT png_count EQUAL 7)
  message(FATAL_ERROR "--frames wrote ${png_count} PNGs, expected 7")
endif()
file(READ ${OUT}/short.json stats)
string(JSON frame_entries LENGTH "${stats}" frames)
if(NOT frame_entries EQUAL 7)
  message(FATAL_ERROR "stats.json frames: ${frame_entries} entries, expected 7")
endif()
string(JSON time GET "${stats}" frames 4 time_step)  # frame 4 of steps 1..3 at 3 per step: 1 + 4/3
if(NOT time GREATER 2.33 OR NOT time LESS 2.34)
  message(FATAL_ERROR "frames[4].time_step ${time}, expected 2.333")
endif()
foreach(key primary_exposure pop_in pop_out cut_flicker context_share cells_opening upload_bytes ms)
  string(JSON value ERROR_VARIABLE missing GET "${stats}" frames 1 ${key})
  if(missing)
    message(FATAL_ERROR "stats.json frames[1] has no ${key}")
  endif()
endforeach()
foreach(key primary_exposure_min cut_flicker_max pop_max context_share_mean gl_renderer lp_num_threads git_revision size cells configuration)
  string(JSON value ERROR_VARIABLE missing GET "${stats}" ${key})
  if(missing)
    message(FATAL_ERROR "stats.json has no ${key}")
  endif()
endforeach()

# none against smooth at the same frames (steps 0..3, 8 frames per step), mean filter off so that
# primary exposure is exactly 1 (README: the frustum's back face covers every primary pixel; the
# mean filter may move the cut over a border pixel). At 8 frames per step the paced changes spread
# each step's pops over 8 frames (8.0x fewer per frame than none here) and cut flicker drops 4.6x;
# at 4 frames per step flicker drops about 2.8x (a step's first changes carve the most new cut),
# so the 3x target is checked at 8.
foreach(mode none smooth)
  execute_process(COMMAND ${CUTAWAY} animate ${PETRA} --steps 0 3 --frames-per-step 8 --mean-filter 0
                          --coherence ${mode} --out ${OUT}/${mode}.mp4 --stats ${OUT}/${mode}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "animate --coherence ${mode} failed (${rc}): ${err}")
  endif()
  file(READ ${OUT}/${mode}.json stats_${mode})
  string(JSON pop_${mode} GET "${stats_${mode}}" pop_max)
  string(JSON flicker_${mode} GET "${stats_${mode}}" cut_flicker_max)
  string(JSON exposure GET "${stats_${mode}}" primary_exposure_min)
  if(NOT exposure EQUAL 1)
    message(FATAL_ERROR "${mode}: primary_exposure_min ${exposure}, expected 1")
  endif()
endforeach()
math(EXPR pop_smooth_3x "3 * ${pop_smooth}")
if(NOT pop_none GREATER_EQUAL pop_smooth_3x)
  message(FATAL_ERROR "pop_max none ${pop_none}, smooth ${pop_smooth}: expected smooth at least 3x lower")
endif()
# CMake compares decimals only through math on integers: flicker in units of 1e-4.
foreach(mode none smooth)
  string(REGEX REPLACE "^0\\.([0-9][0-9][0-9][0-9]).*" "\\1" scaled "${flicker_${mode}}")
  math(EXPR flicker_scaled_${mode} "1${scaled} - 10000")
endforeach()
math(EXPR flicker_smooth_3x "3 * ${flicker_scaled_smooth}")
if(NOT flicker_scaled_none GREATER_EQUAL flicker_smooth_3x)
  message(FATAL_ERROR "cut_flicker_max none ${flicker_none}, smooth ${flicker_smooth}: expected smooth at least 3x lower")
endif()

function(expect_refusal name pattern)
  execute_process(COMMAND ${CUTAWAY} animate ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err)
  # Refusals of the command line add main.cpp's pointer to --help on a second line.
  string(REPLACE "\n(cutaway SUBCOMMAND --help lists the options)" "" err "${err}")
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" newline)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${pattern}" OR NOT newline EQUAL -1)
    message(FATAL_ERROR "${name}: exit ${rc} (expected 2 and one line), message '${err}'")
  endif()
endfunction()
expect_refusal(unwritable_mp4 "--out: expected a file in an existing directory" ${PETRA} --out ${OUT}/missing/a.mp4)
expect_refusal(steps_out_of_range "--steps 2 9: expected 0 <= FIRST <= LAST < 6 \\(SWAT's report steps"
               ${PETRA} --steps 2 9 --out ${OUT}/bad.mp4)
expect_refusal(static_property "--property PORO: expected a property with time steps, found a static one"
               preset:petra --property PORO --range 0.2 0.3 --size 160 120 --out ${OUT}/bad.mp4)
expect_refusal(odd_size "--size: expected an even width and height" preset:petra --property SWAT --range 0.5 1
               --size 161 120 --out ${OUT}/bad.mp4)
expect_refusal(bad_coherence "--coherence" ${PETRA} --coherence sudden --out ${OUT}/bad.mp4)

# An interrupted animate leaves no MP4, not even the partial one: SIGINT after 3 s, while the
# model loads or frames render (the signal is held until the next frame either way).
execute_process(COMMAND timeout -s INT 3 ${CUTAWAY} animate ${PETRA} --steps 0 5 --frames-per-step 50
                        --out ${OUT}/interrupted.mp4
                RESULT_VARIABLE rc ERROR_VARIABLE err)
file(GLOB leftovers ${OUT}/bad.mp4 ${OUT}/.bad.mp4.partial-* ${OUT}/interrupted.mp4 ${OUT}/.interrupted.mp4.partial-*)
if(NOT rc EQUAL 124 OR NOT err MATCHES "interrupted by Interrupt; no MP4 written" OR leftovers)
  message(FATAL_ERROR "interrupted animate: exit ${rc} (expected timeout's 124), message '${err}', left '${leftovers}'")
endif()
