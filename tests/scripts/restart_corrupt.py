#!/usr/bin/env python3
"""restart_corrupt.py CHECKPOINT DIR: writes DIR/corrupt_table.h5 (one byte of the table cell.state's data changed),
DIR/corrupt_text.h5 (the identity text 'hydro' overwritten by '\\xfa\\x01dro') and DIR/corrupt_format.h5 (the format
text's first bytes overwritten likewise), each otherwise the checkpoint itself, and DIR/forged_loop.h5 (the loop's dump
count NaN with its checksum renewed: the values behind a valid checksum are checked too; a NaN index stopped the writer
with an internal error) (tests/regression/restart.cmake)."""
import shutil
import sys

import h5py
import numpy as np

source, work = sys.argv[1], sys.argv[2]
data = open(source, "rb").read()
with h5py.File(source, "r") as f:
    table = f["tables/cell.state"]
    offset = table.id.get_offset() + 8 * table.shape[1] * (table.shape[0] // 2) + 3  # a middle row, a mantissa byte


def write(name, bytes_):
    assert bytes_ != data
    with open(f"{work}/{name}", "wb") as f:
        f.write(bytes_)


corrupt = bytearray(data)
corrupt[offset] ^= 0x10
write("corrupt_table.h5", bytes(corrupt))
assert data.count(b"hydro") == 1 and data.count(b"unilag checkpoint 4") == 1
write("corrupt_text.h5", data.replace(b"hydro", b"\xfa\x01dro"))
write("corrupt_format.h5", data.replace(b"unilag checkpoint 4", b"\xfa\x01ilag checkpoint 4"))


def fnv1a(data):
    h = 0xCBF29CE484222325
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


forged = f"{work}/forged_loop.h5"
shutil.copy(source, forged)
with h5py.File(forged, "r+") as f:
    loop = f["vectors/loop"][()]
    loop[4] = np.nan
    del f["vectors/loop"]
    f["vectors/loop"] = loop
    del f["checksums/list.loop"]
    f["checksums/list.loop"] = np.frombuffer(("%016x" % fnv1a(loop.tobytes())).encode(), np.int8)
