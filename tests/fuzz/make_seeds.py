#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the binary seeds of the fuzz corpora: the programs of corpus/c_api/ (in the encoding
fuzz_c_api.cpp reads), small .npy arrays with missing points for corpus/npy_reader/, and the
hostile files of the readers' limits (docs/robustness.md): x3p archives written byte by byte,
whose headers declare what damaged or malicious archives declare, .npy files declaring more
than they hold and text with decimal commas. The standard library only; the files are
committed and the tests do not run this script:
    python3 tests/fuzz/make_seeds.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

# The table of Input::real() in fuzz_c_api.cpp, by name.
TABLE = ["0", "-0", "1", "-1", "0.5", "2", "0.1", "1e-3", "1e-8", "1e-12", "10", "1e3", "1e10",
         "1e-300", "1e300", "max", "-max", "min", "denorm", "inf", "-inf", "nan", "0.8", "0.05",
         "0.25", "3"]


class Program:
    """The bytes of one input: each method appends one step of the driver's loop."""

    def __init__(self):
        self.b = bytearray()

    def byte(self, v):
        self.b.append(v & 0xFF)

    def real(self, v):
        if isinstance(v, str):
            self.byte(TABLE.index(v))
        elif (v == 0 or 0.01 <= v <= 1.61) and abs(v * 100 - round(v * 100)) < 1e-9:
            self.byte(78 + round(v * 100))
        else:
            self.byte(240)
            self.b += struct.pack(">d", v)

    def grid_2d(self, nx, ny, lx, ly):
        self.byte(0)            # make_grid
        self.byte(0)            # 2D
        self.byte(nx - 1)
        self.byte(ny - 1)
        self.byte(1)            # sizes as given
        self.real(lx)
        self.real(ly)
        self.byte(0)            # ASP_FFT_ESTIMATE

    def grid_1d(self, nx, lx):
        self.byte(0)
        self.byte(1)            # 1D
        self.byte(1)            # nx from one byte
        self.byte(nx - 1)
        self.byte(1)
        self.real(lx)
        self.byte(0)

    def topography(self, which, *args):
        self.byte(2)
        self.byte(1)            # the current grid
        self.byte(5)            # the grid's pixel count
        self.byte(which)
        self.byte(1)            # a real array
        for kind, v in args:
            if kind == "real":
                self.real(v)
            elif kind == "byte":
                self.byte(v)
            elif kind == "i64":
                self.b += struct.pack(">q", v)

    def system(self, slot, periodic, modulus):
        self.byte(4)
        self.byte(slot)
        self.byte(1)            # the current grid
        self.real(modulus)
        self.byte(1 if periodic else 0)

    def setting(self, slot, which, *reals):
        self.byte(5)
        self.byte(slot)
        self.byte(which)
        if which == 0:
            self.byte(5)        # the right count
            self.byte(1)        # the heights
        for v in reals:
            self.real(v)

    def potential(self, slot, mode, after, hard_wall):
        self.byte(5)
        self.byte(slot)
        self.byte(5)
        self.byte(mode)
        self.byte(after)
        self.byte(1)            # the callback
        self.byte(1 if hard_wall else 0)

    def solver(self, slot, algorithm):
        names = ["pk", "bugnicourt", "lbfgsb", "lbfgs", "lbfgs_fourier", "fire",
                 "fire_mass_weighted", "gfmd"]
        self.byte(7)
        self.byte(slot)
        self.byte(names.index(algorithm))

    def option(self, slot, name, value):
        options = ["tolerance", "max_iterations", "stall_window", "variable", "memory",
                   "time_step", "max_time_step", "time_step_growth", "time_step_shrink",
                   "mixing", "mixing_decay", "delay", "damping"]
        self.byte(8)
        self.byte(slot)
        if name == "variable":
            self.byte(1)
            self.byte(options.index(name))
            self.byte(["pressure", "gap"].index(value))
        else:
            self.byte(0)
            self.byte(options.index(name))
            self.real(value)

    def history(self, slot):
        self.byte(8)
        self.byte(slot)
        self.byte(5)
        self.byte(1)

    def cancel_at(self, slot, iteration):
        self.byte(8)
        self.byte(slot)
        self.byte(6)
        self.byte(1)
        self.byte(iteration)
        self.byte(1)

    def solve(self, slot, system_slot, control, value):
        self.byte(9)
        self.byte(slot)
        self.byte(system_slot)
        self.byte({"mean_pressure": 0, "penetration": 1, "mean_gap": 2}[control])
        self.real(value)

    def getter(self, which, *bytes_):
        self.byte(10)
        self.byte(0)
        self.byte(1)
        self.byte(1)
        self.byte(which)
        for v in bytes_:
            self.byte(v)


def self_affine(p):
    p.topography(5, ("real", 0.8), ("real", 1), ("real", 0.25), ("real", 0.1), ("byte", 1),
                 ("byte", 1), ("real", 0.1), ("i64", 42))


def c_api_seeds():
    seeds = {}
    p = Program()  # the README's example, small: pk on a self-affine surface
    p.grid_2d(32, 32, 1, 1)
    self_affine(p)
    p.system(0, True, 1)
    p.setting(0, 0)
    p.solver(0, "pk")
    p.history(0)
    p.option(0, "tolerance", 1e-8)
    p.solve(0, 0, "mean_pressure", 0.01)
    p.getter(0, 0)
    p.getter(2, 5, 4)
    seeds["pk_self_affine"] = p

    p = Program()  # adhesion on a 1D sinusoid, bugnicourt on the gap, then lbfgsb
    p.grid_1d(64, 1)
    p.topography(3, ("byte", 1), ("byte", 0), ("real", 0.1))
    p.system(1, True, 1)
    p.setting(1, 0)
    p.setting(1, 1, 0.01, 0.01)
    p.solver(0, "bugnicourt")
    p.option(0, "variable", "gap")
    p.solve(0, 1, "mean_gap", 0.05)
    p.solver(1, "lbfgsb")
    p.option(1, "variable", "gap")
    p.option(1, "memory", 3)
    p.solve(1, 1, "penetration", 0.05)
    seeds["adhesion_1d"] = p

    p = Program()  # a sphere on the soft wall, preconditioned L-BFGS and FIRE
    p.grid_2d(24, 16, 1, 0.5)
    p.topography(1, ("real", 0.5))
    p.system(0, True, 2)
    p.setting(0, 0)
    p.setting(0, 2, 0.01, 0.01, 0.001, 0.02)
    p.solver(0, "lbfgs_fourier")
    p.solve(0, 0, "mean_pressure", 0.001)
    p.solver(1, "fire_mass_weighted")
    p.cancel_at(1, 5)
    p.solve(1, 0, "penetration", 0.01)
    seeds["soft_wall_sphere"] = p

    p = Program()  # the free substrate under a paraboloid
    p.grid_2d(16, 16, 1, 1)
    p.topography(2, ("real", 2))
    p.system(1, False, 1)
    p.setting(1, 0)
    p.solver(0, "pk")
    p.solve(0, 1, "penetration", 0.01)
    p.getter(1, 5, 0)
    seeds["free_paraboloid"] = p

    p = Program()  # a user potential with the hard wall (lbfgsb), then failing (gfmd, soft)
    p.grid_2d(8, 8, 1, 1)
    p.topography(4, ("real", 0.1), ("real", 0.01), ("byte", 4))
    p.system(0, True, 1)
    p.setting(0, 0)
    p.potential(0, 0, 0, True)
    p.solver(0, "lbfgsb")
    p.option(0, "variable", "gap")
    p.solve(0, 0, "penetration", 0.02)
    p.potential(0, 2, 3, False)
    p.solver(1, "gfmd")
    p.solve(1, 0, "penetration", 0.02)
    seeds["user_potential"] = p

    p = Program()  # Lennard-Jones, plain L-BFGS and FIRE, extreme values
    p.grid_2d(16, 8, 1, 1)
    self_affine(p)
    p.system(0, True, 1)
    p.setting(0, 0)
    p.setting(0, 3, 0.001, 0.01)
    p.solver(0, "lbfgs")
    p.option(0, "memory", 4)
    p.solve(0, 0, "penetration", 0.01)
    p.solver(1, "fire")
    p.option(1, "time_step", "1e300")
    p.solve(1, 0, "penetration", "nan")
    p.setting(0, 6, "1e-300")
    p.setting(0, 7, "inf")
    seeds["lennard_jones_extremes"] = p

    p = Program()  # a soft wall of range 1e20 under load: the penetration is 1e25
    p.grid_2d(31, 31, 1, 1)
    p.topography(1, ("real", 1))
    p.system(0, True, 1)
    p.setting(0, 0)
    p.setting(0, 2, 1e-3, 1e20, 0, 1e20)
    p.setting(0, 6, 1e3)
    p.solver(0, "lbfgs_fourier")
    p.solve(0, 0, "mean_pressure", 1)
    p.getter(0, 0)
    p.solver(1, "gfmd")
    p.option(1, "tolerance", 1e-288)
    p.solve(1, 0, "mean_pressure", 1)
    seeds["soft_wall_far_range"] = p

    p = Program()  # bugnicourt on the gap, mean gap, a tolerance the start already meets
    p.grid_2d(32, 32, 1, 1)
    self_affine(p)
    p.system(0, True, 1)
    p.setting(0, 0)
    p.setting(0, 1, 1e-4, 0.01)
    p.solver(0, "bugnicourt")
    p.option(0, "variable", "gap")
    p.option(0, "tolerance", 1e87)
    p.solve(0, 0, "mean_gap", 0.05)
    p.getter(0, 0)
    seeds["mean_gap_loose_tolerance"] = p
    return seeds


def npy(shape, values, descr="<f8"):
    header = "{'descr': '%s', 'fortran_order': False, 'shape': %s, }" % (descr, shape)
    header += " " * (63 - (10 + len(header)) % 64) + "\n"
    data = b"".join(struct.pack(descr[0] + "d", v) for v in values)
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + data


def deflated(pieces, strategy=zlib.Z_DEFAULT_STRATEGY):
    """Raw deflate (as in zip archives) of the byte strings or (byte, count) runs in pieces:
    the compressed bytes, the CRC-32 and the size of what they inflate to."""
    z = zlib.compressobj(6, zlib.DEFLATED, -15, 8, strategy)
    out, crc, size = [], 0, 0
    for piece in pieces:
        if isinstance(piece, tuple):
            byte, count = piece
            block = byte * min(count, 1 << 20)
            chunks = [block] * (count // len(block)) + [block[:count % len(block)]]
        else:
            chunks = [piece]
        for chunk in chunks:
            crc = zlib.crc32(chunk, crc)
            size += len(chunk)
            out.append(z.compress(chunk))
    out.append(z.flush())
    return b"".join(out), crc, size


def member(name, content=None, deflate=None, size=None, compressed=None):
    """A zip member: its stored bytes (content stored, or a deflated() triple) and what its
    headers declare (the true sizes unless size or compressed say otherwise)."""
    if deflate is not None:
        stored, crc, true_size = deflate
        method = 8
    else:
        stored, crc, true_size, method = content, zlib.crc32(content), len(content), 0
    return {"name": name.encode(), "stored": stored, "method": method, "crc": crc,
            "size": true_size if size is None else size,
            "compressed": len(stored) if compressed is None else compressed}


def zip_archive(members):
    out, directory = b"", b""
    for m in members:
        fields = struct.pack("<HHHHHIIIHH", 20, 0, m["method"], 0, 0x21, m["crc"],
                             m["compressed"], m["size"], len(m["name"]), 0)
        directory += (struct.pack("<IH", 0x02014B50, 20) + fields +
                      struct.pack("<HHHII", 0, 0, 0, 0, len(out)) + m["name"])
        out += struct.pack("<I", 0x04034B50) + fields + m["name"] + m["stored"]
    return out + directory + struct.pack("<IHHHHIIH", 0x06054B50, 0, 0, len(members),
                                         len(members), len(directory), len(out), 0)


XML_START = (b'<?xml version="1.0" encoding="UTF-8"?>\n'
             b'<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">\n')
XML_END = b"</p:ISO5436_2>\n"


def main_xml(nx, ny):
    axis = ("<%s><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-06</Increment>"
            "<Offset>0</Offset></%s>")
    return XML_START + (
        "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>"
        + axis % ("CX", "CX") + axis % ("CY", "CY") +
        "<CZ><AxisType>A</AxisType><DataType>D</DataType></CZ></Axes></Record1>\n"
        "<Record3><MatrixDimension><SizeX>%d</SizeX><SizeY>%d</SizeY><SizeZ>1</SizeZ>"
        "</MatrixDimension><DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
        "</DataLink></Record3>\n" % (nx, ny)).encode() + XML_END


def x3p(xml, data):
    return zip_archive([member("main.xml", deflate=deflated([xml])), data])


def hostile_seeds():
    """The hostile files of tests/io/test_hostile_files.cpp, with bombs of 5 MiB (5 kB
    deflated, beyond the 4 MiB limit of main.xml), so that libFuzzer, which sizes its inputs by
    the largest seed, keeps them small."""
    zeros96 = member("bindata/data.bin", b"\0" * 96)
    bomb = deflated([(b"\0", 5 << 20)], zlib.Z_RLE)
    xml_bomb = deflated([XML_START, (b" ", 5 << 20), XML_END], zlib.Z_RLE)
    nested = XML_START + b"<a>" * 100000 + b"</a>" * 100000 + XML_END
    npy_header = b"{'descr': '<f8', 'fortran_order': False, 'shape': (16384, 16384), }"
    npy_header += b" " * (117 - len(npy_header)) + b"\n"
    return {
        "x3p_reader": {
            "regression-2to28-points-96-bytes.x3p": x3p(main_xml(16384, 16384), zeros96),
            "regression-32768-squared-points.x3p": x3p(main_xml(32768, 32768), zeros96),
            "regression-deflate-cannot-hold.x3p": x3p(
                main_xml(16384, 16384),
                member("bindata/data.bin", deflate=(b"\x55" * 20, 0, 20), size=1 << 31)),
            "regression-bzip2-member.x3p": x3p(
                main_xml(16384, 16384),
                dict(member("bindata/data.bin", b"\x55" * 20, size=1 << 31), method=12)),
            "regression-data-bomb.x3p": x3p(main_xml(4, 3), member("bindata/data.bin",
                                                                   deflate=bomb)),
            "regression-data-bomb-declaring-96-bytes.x3p": x3p(
                main_xml(4, 3), member("bindata/data.bin", deflate=bomb, size=96)),
            "regression-xml-bomb.x3p": zip_archive([member("main.xml", deflate=xml_bomb),
                                                    zeros96]),
            "regression-xml-bomb-declaring-1000-bytes.x3p": zip_archive(
                [member("main.xml", deflate=xml_bomb, size=1000), zeros96]),
            "nested_xml.x3p": x3p(nested, zeros96),
        },
        "npy_reader": {
            "regression-2to28-points-in-128-bytes.npy":
                b"\x93NUMPY\x01\x00" + struct.pack("<H", len(npy_header)) + npy_header,
        },
        "text_reader": {
            "regression-decimal-commas.txt": b"0,5 0,1 0,3\n0,2 0,4 0,6\n",
            "regression-decimal-commas-semicolons.csv": b"# heights\n-1,25;2,5\n3,75;4,0\n",
            "regression-decimal-comma-column.txt": b"0,5\n0,25\n-1,5\n",
            "integers_commas.csv": b"1,2,3\n4,5,6\n",
        },
    }


def main():
    for name, program in c_api_seeds().items():
        with open(os.path.join(HERE, "corpus", "c_api", name), "wb") as f:
            f.write(program.b)
    nan = float("nan")
    arrays = {
        "hole.npy": npy("(3, 4)", [1, 2, 3, 4, 5, nan, nan, 8, 9, 10, 11, 12]),
        "all_missing.npy": npy("(2, 2)", [nan] * 4),
        "huge_shape.npy": npy("(4294967296, 4294967296)", [1.0, 2.0]),
    }
    for name, data in arrays.items():
        with open(os.path.join(HERE, "corpus", "npy_reader", name), "wb") as f:
            f.write(data)
    for driver, files in hostile_seeds().items():
        for name, data in files.items():
            with open(os.path.join(HERE, "corpus", driver, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
