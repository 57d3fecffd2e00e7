#!/usr/bin/env python3
"""Converts MediaPipe's BlazePose .tflite models to ONNX that OpenCV 4.6's dnn module loads.

    tflite_to_onnx.py MODEL.tflite OUT.onnx [--keep-output NAME ...]

Debian has no TFLite runtime, but OpenCV (which the project links) runs ONNX. The pose models
use a dozen TFLite operators (tools/pose_model/README.md); each becomes its ONNX counterpart:

- TFLite computes in NHWC, ONNX (and OpenCV) in NCHW. The ONNX graph takes its input as
  NCHW ([1, 3, H, W], what cv::dnn::blobFromImage makes) and keeps every 4-D activation in
  NCHW; the weights are transposed once here. A RESHAPE of a 4-D activation first transposes
  it back to NHWC, so that its element order is TFLite's.
- Constant-only operators (DEQUANTIZE of the fp16 weights, DENSIFY of the sparse ones) are
  folded: the ONNX file holds plain fp32 weights.
- OpenCV 4.6 reads Clip's bounds from attributes only (the opset-6 form), so RELU6 is
  written that way; the model declares opset 11 for Resize's coordinate modes.
- 4-D outputs (the landmark model's heatmap) stay NCHW.

Only the outputs named by --keep-output are kept (all when none is given), with whatever
feeds them: the landmark model's segmentation mask is not needed and costs time.
"""
import argparse
import os
import struct
import sys

import numpy as np
import onnx
from onnx import TensorProto, helper, numpy_helper

import tflite_reader as tfl

NHWC_TO_NCHW = [0, 3, 1, 2]
NCHW_TO_NHWC = [0, 2, 3, 1]
# A NHWC axis of a 4-D tensor, as an NCHW axis.
NHWC_AXIS_IN_NCHW = {0: 0, 1: 2, 2: 3, 3: 1}
ACTIVATIONS = {0: None, 1: "RELU", 3: "RELU6"}


class ConversionError(ValueError):
    pass


def densify(tensor):
    """The dense values of a TFLite sparse constant (SparsityParameters, no block map)."""
    sparsity = tensor.sparsity
    order = [int(v) for v in sparsity.int_vector(0)]
    if len(sparsity.int_vector(1)) != 0:
        raise ConversionError(f"tensor '{tensor.name}': block-sparse weights are not supported")
    if order != list(range(len(tensor.shape))):
        raise ConversionError(f"tensor '{tensor.name}': traversal order {order} is not supported")
    dims = sparsity.tables(2)
    if len(dims) != len(tensor.shape):
        raise ConversionError(f"tensor '{tensor.name}': {len(dims)} dimension entries for shape {tensor.shape}")
    dense = np.zeros(tensor.shape, dtype=tensor.dtype)
    values = tensor.data.reshape(-1)
    # Walk the dimensions in order; `parents` holds, for every position reached so far, its
    # coordinates and its index at this level (a CSR level's segments are indexed by it).
    positions = [((), 0)]
    for level, dim in enumerate(dims):
        # DimensionMetadata: format (0; 0 dense, 1 CSR), dense_size (1), array_segments (3),
        # array_indices (5); the index vectors are tables whose field 0 holds the values.
        fmt = dim.scalar(0, "b")
        next_positions = []
        if fmt == 0:
            size = dim.scalar(1, "i")
            for coords, index in positions:
                for i in range(size):
                    next_positions.append((coords + (i,), index * size + i))
        else:
            vector_types = {1: "<i4", 2: "<u2", 3: "<u1"}
            seg_type, idx_type = dim.scalar(2, "B"), dim.scalar(4, "B")
            if seg_type not in vector_types or idx_type not in vector_types:
                raise ConversionError(f"tensor '{tensor.name}': unknown sparse index type")
            segments = dim.table(3).int_vector(0, vector_types[seg_type])
            indices = dim.table(5).int_vector(0, vector_types[idx_type])
            for coords, index in positions:
                if index + 1 >= len(segments):
                    raise ConversionError(f"tensor '{tensor.name}': sparse segments too short")
                for k in range(int(segments[index]), int(segments[index + 1])):
                    next_positions.append((coords + (int(indices[k]),), k))
        positions = next_positions
        del level
    if len(positions) != values.size:
        raise ConversionError(f"tensor '{tensor.name}': {values.size} values for {len(positions)} positions")
    for (coords, _), value in zip(positions, values):
        dense[coords] = value
    return dense


def same_padding(in_size, kernel, stride, dilation=1):
    """TensorFlow's SAME padding (before, after) along one axis."""
    effective = (kernel - 1) * dilation + 1
    out = (in_size + stride - 1) // stride
    total = max((out - 1) * stride + effective - in_size, 0)
    return total // 2, total - total // 2


class Converter:
    def __init__(self, model):
        self.model = model
        self.nodes = []
        self.initializers = []
        self.constants = {}  # tensor index -> numpy array (folded)
        self.nchw = set()  # tensor indices held as NCHW 4-D activations
        self.names = {}
        self.counter = 0

    def name(self, index):
        if index not in self.names:
            self.names[index] = f"t{index}"
        return self.names[index]

    def fresh(self, stem):
        self.counter += 1
        return f"{stem}_{self.counter}"

    def initializer(self, array, stem):
        name = self.fresh(stem)
        self.initializers.append(numpy_helper.from_array(np.ascontiguousarray(array), name))
        return name

    def constant(self, index):
        if index in self.constants:
            return self.constants[index]
        t = self.model.tensors[index]
        if t.data is None:
            return None
        if t.sparsity is not None:
            raise ConversionError(f"tensor '{t.name}' is sparse but not densified")
        return t.data

    def shape(self, index):
        return self.model.tensors[index].shape

    def activation(self, x, code, out):
        kind = ACTIVATIONS.get(code, "unsupported")
        if kind == "unsupported":
            raise ConversionError(f"fused activation {code} is not supported")
        if kind is None:
            return x
        if kind == "RELU":
            self.nodes.append(helper.make_node("Relu", [x], [out]))
        else:
            self.nodes.append(helper.make_node("Clip", [x], [out], min=0.0, max=6.0))
        return out

    def emit_with_activation(self, op_type, inputs, out_index, activation_code, **attrs):
        out = self.name(out_index)
        if ACTIVATIONS.get(activation_code) is None:
            if activation_code not in ACTIVATIONS:
                raise ConversionError(f"fused activation {activation_code} is not supported")
            self.nodes.append(helper.make_node(op_type, inputs, [out], **attrs))
        else:
            raw = self.fresh(op_type.lower())
            self.nodes.append(helper.make_node(op_type, inputs, [raw], **attrs))
            self.activation(raw, activation_code, out)

    # [SECTION] operators

    def conv(self, op, depthwise):
        x, w_index = op.inputs[0], op.inputs[1]
        weights = self.constant(w_index)
        if weights is None:
            raise ConversionError("convolution weights are not constant")
        weights = weights.astype(np.float32)
        o = op.options
        padding, stride_w, stride_h = o.scalar(0, "b"), o.scalar(1, "i"), o.scalar(2, "i")
        if depthwise:
            multiplier, act = o.scalar(3, "i"), o.scalar(4, "b")
            dil_w, dil_h = o.scalar(5, "i", 1), o.scalar(6, "i", 1)
            channels = self.shape(x)[3]
            if multiplier != 1 and weights.shape[3] != channels * multiplier:
                raise ConversionError("depthwise multiplier does not match the weights")
            w = weights.transpose(3, 0, 1, 2)  # [1,kh,kw,C*m] -> [C*m,1,kh,kw]
            group = channels
        else:
            act = o.scalar(3, "b")
            dil_w, dil_h = o.scalar(4, "i", 1), o.scalar(5, "i", 1)
            w = weights.transpose(0, 3, 1, 2)  # [O,kh,kw,I] -> [O,I,kh,kw]
            group = 1
        kh, kw = w.shape[2], w.shape[3]
        in_h, in_w = self.shape(x)[1], self.shape(x)[2]
        if padding == 0:
            top, bottom = same_padding(in_h, kh, stride_h, dil_h)
            left, right = same_padding(in_w, kw, stride_w, dil_w)
        else:
            top = bottom = left = right = 0
        inputs = [self.name(x), self.initializer(w, "w")]
        if len(op.inputs) > 2 and op.inputs[2] >= 0:
            bias = self.constant(op.inputs[2])
            inputs.append(self.initializer(bias.astype(np.float32), "b"))
        self.emit_with_activation("Conv", inputs, op.outputs[0], act,
                                  kernel_shape=[kh, kw], strides=[stride_h, stride_w],
                                  dilations=[dil_h, dil_w], pads=[top, left, bottom, right],
                                  group=group)
        self.nchw.add(op.outputs[0])

    def add(self, op):
        a, b = op.inputs
        if self.constant(a) is not None or self.constant(b) is not None:
            raise ConversionError("ADD of a constant is not supported")
        if (a in self.nchw) != (b in self.nchw):
            raise ConversionError("ADD of tensors in different layouts")
        self.emit_with_activation("Add", [self.name(a), self.name(b)], op.outputs[0],
                                  op.options.scalar(0, "b") if op.options else 0)
        if a in self.nchw:
            self.nchw.add(op.outputs[0])

    def pad(self, op):
        x = op.inputs[0]
        pads = self.constant(op.inputs[1])
        if x not in self.nchw or pads is None or pads.shape != (4, 2):
            raise ConversionError("PAD of other than a 4-D activation by constant paddings")
        nchw = pads[NHWC_TO_NCHW]
        values = [int(v) for v in list(nchw[:, 0]) + list(nchw[:, 1])]
        self.nodes.append(helper.make_node(
            "Pad", [self.name(x), self.initializer(np.array(values, dtype=np.int64), "pads")],
            [self.name(op.outputs[0])], mode="constant"))
        self.nchw.add(op.outputs[0])

    def max_pool(self, op):
        x = op.inputs[0]
        o = op.options
        padding, stride_w, stride_h = o.scalar(0, "b"), o.scalar(1, "i"), o.scalar(2, "i")
        kw, kh, act = o.scalar(3, "i"), o.scalar(4, "i"), o.scalar(5, "b")
        in_h, in_w = self.shape(x)[1], self.shape(x)[2]
        if padding == 0:
            top, bottom = same_padding(in_h, kh, stride_h)
            left, right = same_padding(in_w, kw, stride_w)
        else:
            top = bottom = left = right = 0
        self.emit_with_activation("MaxPool", [self.name(x)], op.outputs[0], act,
                                  kernel_shape=[kh, kw], strides=[stride_h, stride_w],
                                  pads=[top, left, bottom, right])
        self.nchw.add(op.outputs[0])

    def resize(self, op):
        x = op.inputs[0]
        size = self.constant(op.inputs[1])
        o = op.options
        align, half_pixel = o.scalar(2, "?", False), o.scalar(3, "?", False)
        mode = "align_corners" if align else ("half_pixel" if half_pixel else "asymmetric")
        in_shape = self.shape(x)
        scales = np.array([1.0, 1.0, size[0] / in_shape[1], size[1] / in_shape[2]], dtype=np.float32)
        roi = self.initializer(np.zeros(0, dtype=np.float32), "roi")
        self.nodes.append(helper.make_node(
            "Resize", [self.name(x), roi, self.initializer(scales, "scales")],
            [self.name(op.outputs[0])], mode="linear", coordinate_transformation_mode=mode))
        self.nchw.add(op.outputs[0])

    def reshape(self, op):
        x = op.inputs[0]
        target = self.shape(op.outputs[0])
        source = self.name(x)
        if x in self.nchw:
            source = self.fresh("nhwc")
            self.nodes.append(helper.make_node("Transpose", [self.name(x)], [source], perm=NCHW_TO_NHWC))
        if len(target) == 4:
            raise ConversionError("RESHAPE to a 4-D tensor is not supported")
        self.nodes.append(helper.make_node(
            "Reshape", [source, self.initializer(np.array(target, dtype=np.int64), "shape")],
            [self.name(op.outputs[0])]))

    def logistic(self, op):
        self.nodes.append(helper.make_node("Sigmoid", [self.name(op.inputs[0])], [self.name(op.outputs[0])]))
        if op.inputs[0] in self.nchw:
            self.nchw.add(op.outputs[0])

    def concatenation(self, op):
        axis, act = op.options.scalar(0, "i"), op.options.scalar(1, "b")
        rank = len(self.shape(op.outputs[0]))
        axis = axis + rank if axis < 0 else axis
        layouts = {i in self.nchw for i in op.inputs}
        if len(layouts) != 1:
            raise ConversionError("CONCATENATION of tensors in different layouts")
        if op.inputs[0] in self.nchw:
            axis = NHWC_AXIS_IN_NCHW[axis]
            self.nchw.add(op.outputs[0])
        self.emit_with_activation("Concat", [self.name(i) for i in op.inputs], op.outputs[0], act, axis=axis)

    def depth_to_space(self, op):
        block = op.options.scalar(0, "i")
        self.nodes.append(helper.make_node("DepthToSpace", [self.name(op.inputs[0])],
                                           [self.name(op.outputs[0])], blocksize=block, mode="DCR"))
        self.nchw.add(op.outputs[0])

    def fold(self, op, name):
        t = self.model.tensors[op.inputs[0]]
        if name == "DENSIFY":
            if t.data is None or t.sparsity is None:
                raise ConversionError("DENSIFY of a tensor that is not a sparse constant")
            self.constants[op.outputs[0]] = densify(t)
        else:
            value = self.constant(op.inputs[0])
            if value is None:
                raise ConversionError("DEQUANTIZE of a tensor that is not constant")
            if value.dtype != np.float16:
                raise ConversionError(f"DEQUANTIZE of {value.dtype} weights is not supported")
            self.constants[op.outputs[0]] = value.astype(np.float32).reshape(self.shape(op.outputs[0]))

    def convert_operator(self, op):
        name = tfl.BUILTIN_NAMES.get(op.code)
        if name in ("DEQUANTIZE", "DENSIFY"):
            self.fold(op, name)
        elif name in ("CONV_2D", "DEPTHWISE_CONV_2D"):
            self.conv(op, depthwise=(name == "DEPTHWISE_CONV_2D"))
        elif name == "ADD":
            self.add(op)
        elif name == "PAD":
            self.pad(op)
        elif name == "MAX_POOL_2D":
            self.max_pool(op)
        elif name == "RESIZE_BILINEAR":
            self.resize(op)
        elif name == "RESHAPE":
            self.reshape(op)
        elif name == "LOGISTIC":
            self.logistic(op)
        elif name == "CONCATENATION":
            self.concatenation(op)
        elif name == "DEPTH_TO_SPACE":
            self.depth_to_space(op)
        else:
            raise ConversionError(f"operator {name or op.code} is not supported")

    # [SECTION] the graph

    def needed_operators(self, outputs):
        """The operators that feed `outputs`, in the model's (topological) order."""
        producer = {}
        for i, op in enumerate(self.model.operators):
            for t in op.outputs:
                producer[t] = i
        needed, stack = set(), list(outputs)
        while stack:
            t = stack.pop()
            if t in producer and producer[t] not in needed:
                needed.add(producer[t])
                stack.extend(self.model.operators[producer[t]].inputs)
        return [op for i, op in enumerate(self.model.operators) if i in needed]

    def convert(self, keep_outputs):
        model = self.model
        if len(model.inputs) != 1:
            raise ConversionError(f"{len(model.inputs)} inputs, expected 1")
        input_index = model.inputs[0]
        input_shape = self.shape(input_index)
        if len(input_shape) != 4:
            raise ConversionError(f"input shape {input_shape} is not NHWC")
        self.names[input_index] = "input"
        self.nchw.add(input_index)
        by_name = {model.tensors[i].name: i for i in model.outputs}
        wanted = list(model.outputs) if not keep_outputs else []
        for name in keep_outputs:
            if name not in by_name:
                raise ConversionError(f"no output named '{name}' (outputs: {', '.join(by_name)})")
            wanted.append(by_name[name])
        for i in wanted:
            self.names[i] = model.tensors[i].name
        for op in self.needed_operators(wanted):
            self.convert_operator(op)
        n, h, w, c = input_shape
        graph_inputs = [helper.make_tensor_value_info("input", TensorProto.FLOAT, [n, c, h, w])]
        graph_outputs = []
        for i in wanted:
            shape = self.shape(i)
            if i in self.nchw:
                shape = [shape[p] for p in NHWC_TO_NCHW]
            graph_outputs.append(helper.make_tensor_value_info(self.name(i), TensorProto.FLOAT, shape))
        graph = helper.make_graph(self.nodes, "pose", graph_inputs, graph_outputs, self.initializers)
        return helper.make_model(graph, producer_name="eigenwalker tflite_to_onnx",
                                 opset_imports=[helper.make_opsetid("", 11)])


def convert_file(source, target, keep_outputs=()):
    model = tfl.read_model(source)
    onnx_model = Converter(model).convert(list(keep_outputs))
    tmp = target + ".tmp"
    onnx.save(onnx_model, tmp)
    os.replace(tmp, target)  # never a half-written model under the final name


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("source")
    parser.add_argument("target")
    parser.add_argument("--keep-output", action="append", default=[])
    args = parser.parse_args(argv)
    try:
        convert_file(args.source, args.target, args.keep_output)
    except (tfl.FlatBufferError, ConversionError, OSError, struct.error, ValueError) as e:
        print(f"tflite_to_onnx: {args.source}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
