# The pose detector's models (issue 52; docs/DETECTOR.md): MediaPipe's BlazePose .tflite files,
# fetched by tools/pose_model/fetch_model.sh (`make deps`) into models/, converted here to the
# ONNX that OpenCV 4.6's dnn module loads (tools/pose_model/tflite_to_onnx.py) in
# ${CMAKE_BINARY_DIR}/models, where the programs look first (video/pose_model_files.cpp).
# Without the fetched files or Python's onnx module the build goes on without them: the
# programs then say that detection needs the models and which command fetches them.
set(EW_POSE_MODEL_PACKAGE_DIR "${CMAKE_SOURCE_DIR}/models/mediapipe-pose-0.5.1675469404"
  CACHE PATH "The fetched @mediapipe/pose models (tools/pose_model/fetch_model.sh)")
set(EW_POSE_MODEL_DIR "${CMAKE_BINARY_DIR}/models")
set(EW_POSE_CONVERTER_DIR "${CMAKE_SOURCE_DIR}/tools/pose_model")

# Debian's python3 first: the onnx module is Debian's python3-onnx, which a python3 of
# pyenv's or a virtualenv's earlier on the PATH does not see.
find_program(EW_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT EW_PYTHON3)
  find_program(EW_PYTHON3 NAMES python3)
endif()
set(EW_POSE_CONVERTER_OK FALSE)
if(EW_PYTHON3)
  execute_process(COMMAND ${EW_PYTHON3} -c "import onnx, numpy"
    RESULT_VARIABLE ew_onnx_check OUTPUT_QUIET ERROR_QUIET)
  if(ew_onnx_check EQUAL 0)
    set(EW_POSE_CONVERTER_OK TRUE)
  endif()
endif()

set(EW_POSE_MODELS_BUILT FALSE)
if(NOT EW_POSE_CONVERTER_OK)
  message(STATUS "pose detector: python3 with onnx and numpy not found (python3-onnx, python3-numpy); "
                 "the models are not converted and detection is unavailable")
elseif(NOT EXISTS "${EW_POSE_MODEL_PACKAGE_DIR}/pose_detection.tflite")
  message(STATUS "pose detector: models not fetched; detection needs them: "
                 "bash tools/pose_model/fetch_model.sh (or make deps), then build again")
else()
  set(ew_converter_sources ${EW_POSE_CONVERTER_DIR}/tflite_to_onnx.py ${EW_POSE_CONVERTER_DIR}/tflite_reader.py)
  set(ew_pose_onnx_files)
  # The landmark models' segmentation mask (Identity_2) is left out: nothing uses it.
  foreach(model detection landmark_lite landmark_full landmark_heavy)
    set(src "${EW_POSE_MODEL_PACKAGE_DIR}/pose_${model}.tflite")
    set(dst "${EW_POSE_MODEL_DIR}/pose_${model}.onnx")
    set(keep)
    if(model MATCHES "^landmark")
      set(keep --keep-output Identity --keep-output Identity_1 --keep-output Identity_3 --keep-output Identity_4)
    endif()
    add_custom_command(OUTPUT ${dst}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${EW_POSE_MODEL_DIR}
      COMMAND ${EW_PYTHON3} ${EW_POSE_CONVERTER_DIR}/tflite_to_onnx.py ${src} ${dst} ${keep}
      DEPENDS ${src} ${ew_converter_sources}
      COMMENT "Converting pose_${model}.tflite to ONNX"
      VERBATIM)
    list(APPEND ew_pose_onnx_files ${dst})
  endforeach()
  add_custom_target(pose_models ALL DEPENDS ${ew_pose_onnx_files})
  set(EW_POSE_MODELS_BUILT TRUE)
endif()
