"""A reader for the parts of a TensorFlow Lite model (.tflite) the pose models use.

A .tflite file is a FlatBuffer with the schema of TensorFlow's `lite/schema/schema.fbs`.
Debian ships no TFLite runtime or schema bindings, so the few tables needed are read here
by hand: each table is a vtable of field offsets, and a field is found by its slot number
in the schema (the comments give the schema's field names).
"""
import struct

import numpy as np


class FlatBufferError(ValueError):
    pass


class Table:
    """One FlatBuffer table: `pos` is where the table starts in `buf`."""

    def __init__(self, buf, pos):
        self.buf = buf
        self.pos = pos
        if pos < 0 or pos + 4 > len(buf):
            raise FlatBufferError(f"table at byte {pos} lies outside the file")
        vtable = pos - struct.unpack_from("<i", buf, pos)[0]
        if vtable < 0 or vtable + 4 > len(buf):
            raise FlatBufferError(f"vtable of table at byte {pos} lies outside the file")
        self.vtable = vtable
        self.vtable_size = struct.unpack_from("<H", buf, vtable)[0]

    def _field_pos(self, slot):
        entry = 4 + 2 * slot
        if entry + 2 > self.vtable_size:
            return None
        offset = struct.unpack_from("<H", self.buf, self.vtable + entry)[0]
        return None if offset == 0 else self.pos + offset

    def scalar(self, slot, fmt, default=0):
        p = self._field_pos(slot)
        return default if p is None else struct.unpack_from("<" + fmt, self.buf, p)[0]

    def _indirect(self, p):
        return p + struct.unpack_from("<I", self.buf, p)[0]

    def table(self, slot):
        p = self._field_pos(slot)
        return None if p is None else Table(self.buf, self._indirect(p))

    def _vector(self, slot):
        p = self._field_pos(slot)
        if p is None:
            return None, 0
        start = self._indirect(p)
        if start + 4 > len(self.buf):
            raise FlatBufferError(f"vector at byte {start} lies outside the file")
        count = struct.unpack_from("<I", self.buf, start)[0]
        return start + 4, count

    def vector_bytes(self, slot, element_size=1):
        start, count = self._vector(slot)
        if start is None:
            return b""
        end = start + count * element_size
        if end > len(self.buf):
            raise FlatBufferError(f"vector at byte {start} runs past the end of the file")
        return self.buf[start:end]

    def int_vector(self, slot, dtype="<i4"):
        size = np.dtype(dtype).itemsize
        return np.frombuffer(self.vector_bytes(slot, size), dtype=dtype).astype(np.int64)

    def tables(self, slot):
        start, count = self._vector(slot)
        if start is None:
            return []
        if start + 4 * count > len(self.buf):
            raise FlatBufferError(f"table vector at byte {start} runs past the end of the file")
        return [Table(self.buf, self._indirect(start + 4 * i)) for i in range(count)]

    def string(self, slot):
        return self.vector_bytes(slot).decode("utf-8", errors="replace")


# BuiltinOperator codes (schema.fbs) of the operators the pose models use.
BUILTIN_NAMES = {
    0: "ADD", 2: "CONCATENATION", 3: "CONV_2D", 4: "DEPTHWISE_CONV_2D", 5: "DEPTH_TO_SPACE",
    6: "DEQUANTIZE", 14: "LOGISTIC", 17: "MAX_POOL_2D", 19: "RELU", 21: "RELU6",
    22: "RESHAPE", 23: "RESIZE_BILINEAR", 34: "PAD", 124: "DENSIFY",
}
# TensorType: the element types that occur.
TENSOR_DTYPES = {0: np.float32, 1: np.float16, 2: np.int32, 4: np.int64, 9: np.int8, 3: np.uint8}


class Tensor:
    def __init__(self, index, shape, dtype, name, data, sparsity):
        self.index = index
        self.shape = shape
        self.dtype = dtype
        self.name = name
        self.data = data  # numpy array for a constant, else None
        self.sparsity = sparsity  # the raw Sparsity table of a sparse constant, else None


class Operator:
    def __init__(self, code, inputs, outputs, options):
        self.code = code
        self.inputs = inputs
        self.outputs = outputs
        self.options = options  # Table or None


class Model:
    def __init__(self, tensors, operators, inputs, outputs):
        self.tensors = tensors
        self.operators = operators
        self.inputs = inputs
        self.outputs = outputs


def _operator_code(table):
    # OperatorCode: deprecated_builtin_code (slot 0, byte), builtin_code (slot 3, int).
    deprecated = table.scalar(0, "b")
    builtin = table.scalar(3, "i")
    return max(deprecated, builtin)


def read_model(path):
    with open(path, "rb") as f:
        buf = f.read()
    if len(buf) < 8 or buf[4:8] != b"TFL3":
        raise FlatBufferError(f"{path}: not a TensorFlow Lite model (no 'TFL3' identifier)")
    root = Table(buf, struct.unpack_from("<I", buf, 0)[0])
    # Model: operator_codes (1), subgraphs (2), buffers (4).
    codes = [_operator_code(t) for t in root.tables(1)]
    subgraphs = root.tables(2)
    if len(subgraphs) != 1:
        raise FlatBufferError(f"{path}: {len(subgraphs)} subgraphs, expected 1")
    buffers = root.tables(4)
    graph = subgraphs[0]
    tensors = []
    # SubGraph: tensors (0), inputs (1), outputs (2), operators (3).
    for i, t in enumerate(graph.tables(0)):
        # Tensor: shape (0), type (1), buffer (2), name (3), sparsity (6).
        shape = [int(v) for v in t.int_vector(0)]
        type_code = t.scalar(1, "b")
        if type_code not in TENSOR_DTYPES:
            raise FlatBufferError(f"{path}: tensor {i} has unsupported type {type_code}")
        dtype = TENSOR_DTYPES[type_code]
        buffer_index = t.scalar(2, "I")
        if buffer_index >= len(buffers):
            raise FlatBufferError(f"{path}: tensor {i} names buffer {buffer_index} of {len(buffers)}")
        raw = buffers[buffer_index].vector_bytes(0)
        data = np.frombuffer(raw, dtype=dtype).copy() if raw else None
        sparsity = t.table(6)
        if data is not None and sparsity is None:
            if data.size != int(np.prod(shape)):
                raise FlatBufferError(f"{path}: tensor {i} holds {data.size} values for shape {shape}")
            data = data.reshape(shape)
        tensors.append(Tensor(i, shape, dtype, t.string(3), data, sparsity))
    operators = []
    for op in graph.tables(3):
        # Operator: opcode_index (0), inputs (1), outputs (2), builtin_options (4).
        code_index = op.scalar(0, "I")
        if code_index >= len(codes):
            raise FlatBufferError(f"{path}: operator names code {code_index} of {len(codes)}")
        operators.append(Operator(codes[code_index], [int(v) for v in op.int_vector(1)],
                                  [int(v) for v in op.int_vector(2)], op.table(4)))
    return Model(tensors, operators, [int(v) for v in graph.int_vector(1)],
                 [int(v) for v in graph.int_vector(2)])
