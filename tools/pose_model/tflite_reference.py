"""A slow, plain NumPy interpreter of the TFLite operators the pose models use, in TFLite's
own NHWC layout, written from the operators' definitions: the converter's check.

The converter rewrites the graph for NCHW and OpenCV; this interpreter does none of that,
so agreement between the two (tests/video/test_pose_model_conversion.py) says the layout
changes, the padding rules and the folded weights are right.
"""
import numpy as np

import tflite_reader as tfl
from tflite_to_onnx import densify, same_padding

ACTIVATION = {0: lambda x: x, 1: lambda x: np.maximum(x, 0), 3: lambda x: np.clip(x, 0, 6)}


def _pad_hw(x, kh, kw, sh, sw, padding, dh=1, dw=1):
    if padding != 0:  # VALID
        return x
    top, bottom = same_padding(x.shape[1], kh, sh, dh)
    left, right = same_padding(x.shape[2], kw, sw, dw)
    return np.pad(x, ((0, 0), (top, bottom), (left, right), (0, 0)))


def _windows(x, kh, kw, sh, sw, dh=1, dw=1):
    """[N, OH, OW, kh, kw, C] views of x's receptive fields."""
    n, h, w, c = x.shape
    oh = (h - (kh - 1) * dh - 1) // sh + 1
    ow = (w - (kw - 1) * dw - 1) // sw + 1
    s = x.strides
    return np.lib.stride_tricks.as_strided(
        x, (n, oh, ow, kh, kw, c), (s[0], s[1] * sh, s[2] * sw, s[1] * dh, s[2] * dw, s[3]))


def conv2d(x, w, b, o):
    padding, sw, sh, act = o.scalar(0, "b"), o.scalar(1, "i"), o.scalar(2, "i"), o.scalar(3, "b")
    dw, dh = o.scalar(4, "i", 1), o.scalar(5, "i", 1)
    x = _pad_hw(x, w.shape[1], w.shape[2], sh, sw, padding, dh, dw)
    win = _windows(x, w.shape[1], w.shape[2], sh, sw, dh, dw)
    y = np.einsum("nhwijc,oijc->nhwo", win, w, optimize=True)
    return ACTIVATION[act](y + b)


def depthwise(x, w, b, o):
    padding, sw, sh = o.scalar(0, "b"), o.scalar(1, "i"), o.scalar(2, "i")
    act, dw, dh = o.scalar(4, "b"), o.scalar(5, "i", 1), o.scalar(6, "i", 1)
    x = _pad_hw(x, w.shape[1], w.shape[2], sh, sw, padding, dh, dw)
    win = _windows(x, w.shape[1], w.shape[2], sh, sw, dh, dw)
    y = np.einsum("nhwijc,ijc->nhwc", win, w[0], optimize=True)
    return ACTIVATION[act](y + b)


def max_pool(x, o):
    padding, sw, sh = o.scalar(0, "b"), o.scalar(1, "i"), o.scalar(2, "i")
    kw, kh, act = o.scalar(3, "i"), o.scalar(4, "i"), o.scalar(5, "b")
    if padding == 0:
        top, bottom = same_padding(x.shape[1], kh, sh)
        left, right = same_padding(x.shape[2], kw, sw)
        x = np.pad(x, ((0, 0), (top, bottom), (left, right), (0, 0)), constant_values=-np.inf)
    return ACTIVATION[act](_windows(x, kh, kw, sh, sw).max(axis=(3, 4)))


def resize_bilinear(x, size, o):
    align, half = o.scalar(2, "?", False), o.scalar(3, "?", False)
    out = np.empty((x.shape[0], size[0], size[1], x.shape[3]), dtype=np.float32)

    def source(out_len, in_len):
        i = np.arange(out_len, dtype=np.float64)
        if align and out_len > 1:
            s = i * (in_len - 1) / (out_len - 1)
        elif half:
            s = (i + 0.5) * in_len / out_len - 0.5
        else:
            s = i * in_len / out_len
        s = np.clip(s, 0, in_len - 1)
        lo = np.floor(s).astype(int)
        hi = np.minimum(lo + 1, in_len - 1)
        return lo, hi, (s - lo)[:, None]

    ylo, yhi, fy = source(size[0], x.shape[1])
    xlo, xhi, fx = source(size[1], x.shape[2])
    for n in range(x.shape[0]):
        rows = x[n, ylo] * (1 - fy[:, :, None]) + x[n, yhi] * fy[:, :, None]
        out[n] = rows[:, xlo] * (1 - fx) + rows[:, xhi] * fx
    return out


def depth_to_space(x, block):
    n, h, w, c = x.shape
    y = x.reshape(n, h, w, block, block, c // (block * block))
    return y.transpose(0, 1, 3, 2, 4, 5).reshape(n, h * block, w * block, c // (block * block))


def run(model, image_nhwc):
    """Every output of `model` for one NHWC float input, by tensor name."""
    values = {model.inputs[0]: image_nhwc.astype(np.float32)}

    def get(i):
        if i in values:
            return values[i]
        t = model.tensors[i]
        return t.data

    for op in model.operators:
        name = tfl.BUILTIN_NAMES.get(op.code)
        ins = op.inputs
        o = op.options
        if name == "DENSIFY":
            y = densify(model.tensors[ins[0]])
        elif name == "DEQUANTIZE":
            y = get(ins[0]).astype(np.float32).reshape(model.tensors[op.outputs[0]].shape)
        elif name == "CONV_2D":
            y = conv2d(get(ins[0]), get(ins[1]).astype(np.float32), get(ins[2]).astype(np.float32), o)
        elif name == "DEPTHWISE_CONV_2D":
            y = depthwise(get(ins[0]), get(ins[1]).astype(np.float32), get(ins[2]).astype(np.float32), o)
        elif name == "ADD":
            y = ACTIVATION[o.scalar(0, "b") if o else 0](get(ins[0]) + get(ins[1]))
        elif name == "PAD":
            y = np.pad(get(ins[0]), [tuple(p) for p in get(ins[1])])
        elif name == "MAX_POOL_2D":
            y = max_pool(get(ins[0]), o)
        elif name == "RESIZE_BILINEAR":
            y = resize_bilinear(get(ins[0]), get(ins[1]), o)
        elif name == "RESHAPE":
            y = get(ins[0]).reshape(model.tensors[op.outputs[0]].shape)
        elif name == "LOGISTIC":
            y = 1 / (1 + np.exp(-get(ins[0])))
        elif name == "CONCATENATION":
            y = ACTIVATION[o.scalar(1, "b")](np.concatenate([get(i) for i in ins], axis=o.scalar(0, "i")))
        elif name == "DEPTH_TO_SPACE":
            y = depth_to_space(get(ins[0]), o.scalar(0, "i"))
        else:
            raise ValueError(f"operator {name or op.code} is not supported")
        values[op.outputs[0]] = y
    return {model.tensors[i].name: values[i] for i in model.outputs}
