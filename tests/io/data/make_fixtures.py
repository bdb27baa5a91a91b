#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the fixtures of tests/io/test_height_map_files.cpp with NumPy and the standard
library (zipfile, hashlib), independently of asperity_io's writers. Run from anywhere:
    python3 make_fixtures.py
The tests read the committed files and do not run this script.

The common matrix has 3 rows (y) and 4 columns (x): value(y, x) = 10 y + x + 0.5 (integers:
10 y + x - 5), so that a reader that swaps x and y or transposes is caught.
"""
import hashlib
import io
import os
import struct
import zipfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
NY, NX = 3, 4
MATRIX = np.array([[10.0 * y + x + 0.5 for x in range(NX)] for y in range(NY)])
INTS = np.array([[10 * y + x - 5 for x in range(NX)] for y in range(NY)])


def path(name):
    return os.path.join(HERE, name)


def write_bytes(name, data):
    with open(path(name), "wb") as f:
        f.write(data)


# ---- .npy ----------------------------------------------------------------------------------
np.save(path("c_order.npy"), MATRIX)
np.save(path("fortran_order.npy"), np.asfortranarray(MATRIX))
np.save(path("float32.npy"), MATRIX.astype(np.float32))
np.save(path("big_endian.npy"), MATRIX.astype(">f8"))
np.save(path("int16.npy"), INTS.astype("<i2"))
np.save(path("int64_fortran.npy"), np.asfortranarray(INTS.astype("<i8")))
np.save(path("profile.npy"), np.array([1.5, -2.25, 3.0, 4.125, 5.0]))
with open(path("version2.npy"), "wb") as f:
    np.lib.format.write_array(f, MATRIX, version=(2, 0))
with open(path("version3.npy"), "wb") as f:
    np.lib.format.write_array(f, MATRIX, version=(3, 0))
np.save(path("object.npy"), np.array([1.0, "a"], dtype=object), allow_pickle=True)
np.save(path("three_d.npy"), np.zeros((2, 2, 2)))
np.save(path("complex.npy"), np.zeros(3, dtype=np.complex128))
np.save(path("infinite.npy"), np.array([1.0, np.inf]))
good = open(path("c_order.npy"), "rb").read()
write_bytes("truncated.npy", good[:-12])
write_bytes("bad_magic.npy", b"\x93NUMPZ" + good[6:])

# ---- text ----------------------------------------------------------------------------------
np.savetxt(path("savetxt_comments.txt"), MATRIX, header="made by numpy.savetxt\nsecond line",
           footer="the end")
np.savetxt(path("savetxt_commas.csv"), MATRIX, delimiter=",")
np.savetxt(path("savetxt_semicolons.csv"), MATRIX, delimiter=";", fmt="%.6g")
with_nan = MATRIX.copy()
with_nan[1, 2] = np.nan
np.savetxt(path("savetxt_nan.txt"), with_nan, delimiter="\t")
np.savetxt(path("savetxt_profile.txt"), MATRIX[:1])

# Gwyddion's "ASCII data matrix" export with its informational header, values in metres.
gwy = ["# Channel: Height", "# Width: 10.000 \u00b5m", "# Height: 7.500 \u00b5m",
       "# Value units: m"]
for y in range(NY):
    gwy.append("\t".join("%.6e" % (MATRIX[y, x] * 1e-9) for x in range(NX)))
write_bytes("gwyddion.txt", ("\n".join(gwy) + "\n").encode("utf-8"))

# MATLAB's `save -ascii` (8 significant digits, leading blanks, NaN), with a '%' comment.
mat = ["% heights from MATLAB"]
for y in range(NY):
    mat.append("".join("   %.7e" % MATRIX[y, x] if not (y == 0 and x == 3) else "         NaN"
                       for x in range(NX)))
write_bytes("matlab.txt", ("\r\n".join(mat) + "\r\n").encode())

write_bytes("ragged.txt", b"1 2 3\n4 5 6\n7 8\n")
write_bytes("word.txt", b"# a comment\n1 2 3\n4 five 6\n")
write_bytes("infinite.txt", b"1 2\n3 inf\n")
write_bytes("empty.txt", b"")
write_bytes("only_comments.txt", b"# nothing here\n\n")

# ---- .x3p ----------------------------------------------------------------------------------
def axis(name, increment):
    return ("<%s><AxisType>I</AxisType><DataType>D</DataType><Increment>%r</Increment>"
            "<Offset>0</Offset></%s>" % (name, increment, name))


def main_xml(feature, sx, sy, z_type, record3_body, cz_extra="", cx="", cy=""):
    cx = cx or axis("CX", 1e-6)
    cy = cy or axis("CY", 2e-6)
    return ("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">\n"
            "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>%s</FeatureType>"
            "<Axes>%s%s<CZ><AxisType>A</AxisType><DataType>%s</DataType>%s</CZ></Axes>"
            "</Record1>\n"
            "<Record2><Date>2024-01-01T00:00:00+00:00</Date><Creator>make_fixtures.py</Creator>"
            "</Record2>\n"
            "<Record3><MatrixDimension><SizeX>%d</SizeX><SizeY>%d</SizeY><SizeZ>1</SizeZ>"
            "</MatrixDimension>%s</Record3>\n"
            "<Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>\n"
            "</p:ISO5436_2>\n" % (feature, cx, cy, z_type, cz_extra, sx, sy, record3_body))


def data_link(data, md5=None, valid=None):
    body = "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
    body += "<MD5ChecksumPointData>%s</MD5ChecksumPointData>" % (
        md5 or hashlib.md5(data).hexdigest().upper())
    if valid is not None:
        body += "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
        body += "<MD5ChecksumValidPoints>%s</MD5ChecksumValidPoints>" % (
            hashlib.md5(valid).hexdigest())
    return body + "</DataLink>"


def write_x3p(name, xml, files):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as z:
        if xml is not None:
            z.writestr("main.xml", xml)
            z.writestr("md5checksum.hex",
                       hashlib.md5(xml.encode()).hexdigest() + " *main.xml\n")
        for entry, data in files.items():
            z.writestr(entry, data)
    write_bytes(name, buffer.getvalue())


# Heights in metres, x fastest (row-major (y, x) order is x fastest).
surface = MATRIX * 1e-9
surface_bin = surface.astype("<f8").tobytes()
surface_nan = surface.copy()
surface_nan[2, 1] = np.nan
write_x3p("surface.x3p", main_xml("SUR", NX, NY, "D", data_link(surface_bin)),
          {"bindata/data.bin": surface_bin})
nan_bin = surface_nan.astype("<f4").tobytes()
write_x3p("surface_float32_nan.x3p", main_xml("SUR", NX, NY, "F", data_link(nan_bin)),
          {"bindata/data.bin": nan_bin})

# Integer data scaled by CZ's Increment and Offset, with a valid-points mask: bit i of the
# mask (LSB first) is point i, x fastest; points 1 and 10 are invalid.
int_bin = INTS.astype("<i2").tobytes()
valid = [1] * (NX * NY)
valid[1] = 0
valid[10] = 0
mask = bytearray((NX * NY + 7) // 8)
for i, bit in enumerate(valid):
    mask[i // 8] |= bit << (i % 8)
write_x3p("integer_mask.x3p",
          main_xml("SUR", NX, NY, "I", data_link(int_bin, valid=bytes(mask)),
                   cz_extra="<Increment>1e-09</Increment><Offset>2e-09</Offset>"),
          {"bindata/data.bin": int_bin, "bindata/valid.bin": bytes(mask)})

profile = np.array([1.0, 2.0, 4.0, 8.0, 16.0]) * 1e-6
profile_bin = profile.astype("<f8").tobytes()
write_x3p("profile.x3p", main_xml("PRF", 5, 1, "D", data_link(profile_bin)),
          {"bindata/data.bin": profile_bin})

datums = "".join("<Datum>%r</Datum>" % v for v in surface.flatten())
write_x3p("datalist.x3p", main_xml("SUR", NX, NY, "D", "<DataList>%s</DataList>" % datums), {})

write_x3p("wrong_md5.x3p",
          main_xml("SUR", NX, NY, "D", data_link(surface_bin, md5="0" * 32)),
          {"bindata/data.bin": surface_bin})
write_x3p("no_main_xml.x3p", None, {"bindata/data.bin": surface_bin})
write_x3p("missing_bin.x3p", main_xml("SUR", NX, NY, "D", data_link(surface_bin)), {})
write_x3p("absolute_axis.x3p",
          main_xml("SUR", NX, NY, "D", data_link(surface_bin),
                   cx="<CX><AxisType>A</AxisType><DataType>D</DataType></CX>"),
          {"bindata/data.bin": surface_bin})

# huge_declared_entry.x3p is not made here: an 812-byte archive found by fuzzing the x3p reader
# (tests/fuzz), whose central directory declares an entry of 4244636518 bytes.
