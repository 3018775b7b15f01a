# video_ffmpeg_test.cmake: -video end to end with the real ffmpeg.
#
#   cmake -DPROGRAM=<window_drive> -DWORK_DIR=<dir> -P video_ffmpeg_test.cmake
#
# The program renders 24 frames at 160x120 keeping every second one
# (-every 2: frames 0, 2, ..., 22, so 12), once as an H.264 MP4 and once as
# a GIF; ffprobe decodes each file and must count 12 frames of 160x120 in
# the expected codec. Prints SKIPPED (CTest skips the test) only when
# ffmpeg or ffprobe is not installed; scripts/install-deps.sh installs them.
cmake_minimum_required(VERSION 3.22)

find_program(FFMPEG ffmpeg)
find_program(FFPROBE ffprobe)
if(NOT FFMPEG OR NOT FFPROBE)
  message("SKIPPED: ffmpeg is not installed (Debian package ffmpeg; scripts/install-deps.sh installs it)")
  return()
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
foreach(kind IN ITEMS mp4:h264 gif:gif)
  string(REPLACE ":" ";" kind "${kind}")
  list(GET kind 0 ext)
  list(GET kind 1 codec)
  set(video "${WORK_DIR}/ride.${ext}")
  execute_process(COMMAND "${PROGRAM}" -gl -frames 24 -every 2 -size 160x120 -video "${video}"
    WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${video}")
    message(FATAL_ERROR "the program made no ${video} (exit ${rc}):\n${out}")
  endif()
  execute_process(COMMAND "${FFPROBE}" -v error -count_frames -select_streams v:0
      -show_entries stream=codec_name,width,height,nb_read_frames -of csv=p=0 "${video}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE probe ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ffprobe cannot read ${video}: ${err}")
  endif()
  if(NOT probe STREQUAL "${codec},160,120,12")
    message(FATAL_ERROR "${video}: ffprobe says '${probe}', expected '${codec},160,120,12' "
      "(codec, width, height, frames)")
  endif()
  message(STATUS "${video}: ${probe} (codec, width, height, frames)")
endforeach()
