#!/usr/bin/env python3
"""The pose-model converter (tools/pose_model/tflite_to_onnx.py), checked two ways:

- on the real models: each converted ONNX, run by OpenCV's dnn module (what the programs
  run), gives the outputs of an independent NumPy interpretation of the .tflite in TFLite's
  own NHWC layout (tools/pose_model/tflite_reference.py), on a frame of a real video;
- on hostile files: a truncated model, a file that is no model, and an out-of-range offset
  end in a one-line error naming the file, exit 1, and no output file.

Run by ctest (tests/CMakeLists.txt). The real-model tests need the fetched models
(tools/pose_model/fetch_model.sh): without them they skip, or fail when
EIGENWALKER_REQUIRE_DATA=1. Exit 77 (ctest's skip) when any test skipped and none failed.
"""
import os
import struct
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "pose_model"))
import tflite_reader  # noqa: E402
import tflite_reference  # noqa: E402
import tflite_to_onnx  # noqa: E402

PACKAGE = os.environ.get("EW_POSE_MODEL_PACKAGE_DIR",
                         os.path.join(ROOT, "models", "mediapipe-pose-0.5.1675469404"))
SHARED = os.environ.get("EW_SHARED_DATA_DIR", os.path.join(ROOT, "..", "shared", "data"))
CONVERTER = os.path.join(ROOT, "tools", "pose_model", "tflite_to_onnx.py")
REQUIRED = os.environ.get("EIGENWALKER_REQUIRE_DATA") == "1"


def need(path, what):
    if os.path.exists(path):
        return
    message = f"{what} not found at {path} (fetch: bash tools/pose_model/fetch_model.sh)"
    if REQUIRED:
        raise AssertionError(message + " and EIGENWALKER_REQUIRE_DATA=1")
    raise unittest.SkipTest(message)


def test_image(size, value_range):
    """A real frame (the walking video's frame 100, its left square) resized to the model's
    input, RGB as the models take it; a fixed pseudo-random image without the shared data."""
    import cv2
    video = os.path.join(SHARED, "video", "sports2d-demo", "demo.mp4")
    image = None
    if os.path.exists(video):
        capture = cv2.VideoCapture(video)
        capture.set(cv2.CAP_PROP_POS_FRAMES, 100)
        ok, frame = capture.read()
        if ok:
            side = min(frame.shape[:2])
            image = cv2.resize(frame[:side, :side], (size, size))[:, :, ::-1].astype(np.float32) / 255
    if image is None:
        image = np.random.RandomState(7).rand(size, size, 3).astype(np.float32)
    lo, hi = value_range
    return image * (hi - lo) + lo


class RealModels(unittest.TestCase):
    # (file, input size, input range): the detector takes [-1, 1], the landmark models [0, 1].
    MODELS = [("pose_detection.tflite", 224, (-1, 1)), ("pose_landmark_lite.tflite", 256, (0, 1)),
              ("pose_landmark_full.tflite", 256, (0, 1)), ("pose_landmark_heavy.tflite", 256, (0, 1))]

    @staticmethod
    def kept_outputs(name):
        # As the build converts them (cmake/pose_models.cmake): the landmark models without
        # their segmentation mask, which nothing uses.
        return ["Identity", "Identity_1", "Identity_3", "Identity_4"] if "landmark" in name else []

    def test_opencv_runs_each_converted_model_as_the_tflite_defines_it(self):
        import cv2
        for name, size, value_range in self.MODELS:
            source = os.path.join(PACKAGE, name)
            need(source, "the fetched pose model")
            with self.subTest(model=name), tempfile.TemporaryDirectory() as tmp:
                target = os.path.join(tmp, "model.onnx")
                tflite_to_onnx.convert_file(source, target, self.kept_outputs(name))
                image = test_image(size, value_range)
                expected = tflite_reference.run(tflite_reader.read_model(source), image[None])
                net = cv2.dnn.readNetFromONNX(target)
                net.setInput(np.ascontiguousarray(image.transpose(2, 0, 1)[None]))
                names = net.getUnconnectedOutLayersNames()
                expected = {k: v for k, v in expected.items() if k in names}
                self.assertEqual(len(expected), len(self.kept_outputs(name)) or 2)
                for out_name, got in zip(names, net.forward(names)):
                    want = expected[out_name]
                    if want.ndim == 4:  # 4-D outputs stay NCHW in the ONNX model
                        want = want.transpose(0, 3, 1, 2)
                    self.assertEqual(got.shape, want.shape, out_name)
                    # fp32 sums in another order: 1e-5 of the output's scale (landmarks are in
                    # 256-px input pixels: 2.5e-3 px).
                    scale = max(1.0, float(np.abs(want).max()))
                    self.assertLess(float(np.abs(got - want).max()), 1e-5 * scale, out_name)


class HostileFiles(unittest.TestCase):
    def run_converter(self, data):
        with tempfile.TemporaryDirectory() as tmp:
            source = os.path.join(tmp, "hostile.tflite")
            target = os.path.join(tmp, "out.onnx")
            with open(source, "wb") as f:
                f.write(data)
            run = subprocess.run([sys.executable, CONVERTER, source, target],
                                 capture_output=True, text=True, timeout=60)
            self.assertEqual(run.returncode, 1, run.stderr)
            self.assertIn("hostile.tflite", run.stderr)
            self.assertEqual(len(run.stderr.strip().splitlines()), 1, run.stderr)
            self.assertFalse(os.path.exists(target))
            self.assertFalse(os.path.exists(target + ".tmp"))
            return run.stderr

    def test_a_file_that_is_no_model_is_named(self):
        self.assertIn("not a TensorFlow Lite model", self.run_converter(b"GIF89a not a model at all"))
        self.assertIn("not a TensorFlow Lite model", self.run_converter(b""))

    def test_offsets_past_the_end_are_errors_not_crashes(self):
        # The root offset points past the end; then a vtable offset that does.
        self.assertIn("outside the file", self.run_converter(struct.pack("<I", 4096) + b"TFL3"))
        table_at_8 = struct.pack("<I", 8) + b"TFL3" + struct.pack("<i", -100000)
        self.assertIn("outside the file", self.run_converter(table_at_8))

    def test_a_huge_vector_count_is_refused_before_reading(self):
        # A vtable at byte 8 (slot 1, the operator codes, at +4), the model table at 16, and
        # at 24 the operator codes' vector, whose count says 2^31 - 1 entries.
        vtable = struct.pack("<HHHH", 8, 8, 0, 4)
        table = struct.pack("<i", 16 - 8) + struct.pack("<I", 4)
        data = struct.pack("<I", 16) + b"TFL3" + vtable + table + struct.pack("<I", 0x7FFFFFFF)
        self.assertIn("past the end", self.run_converter(data))

    def test_every_truncation_of_a_real_model_is_an_error(self):
        source = os.path.join(PACKAGE, "pose_detection.tflite")
        need(source, "the fetched pose model")
        with open(source, "rb") as f:
            data = f.read()
        for cut in (7, 64, 4096, len(data) // 2, len(data) - 1000):
            with self.subTest(cut=cut):
                self.run_converter(data[:cut])


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    if result.failures or result.errors:
        sys.exit(1)
    sys.exit(77 if result.skipped else 0)
