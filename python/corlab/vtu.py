"""Field snapshots of corlab runs: the ASCII .vtu files of ``corlab simulate --set
output.times=...`` (include/corlab/fem/output/vtu_writer.hpp) read back as arrays."""
# SPDX-License-Identifier: BSD-3-Clause
from __future__ import annotations

import os


def read_vtu(path):
    """An ASCII .vtu of corlab's writer (include/corlab/fem/output/vtu_writer.hpp) as a dict:
    ``points`` (N x 3, deformed: (r, z, 0) of the axisymmetric model, (x, y, z) of the 3-D one
    [m]), ``quads`` (M x 4 node indices) or ``hexes`` (M x 8, the 3-D model), ``cells``
    {name: (M,) or (M x k)} and ``point_data`` {name: (N,) or (N x k)}."""
    import xml.etree.ElementTree as ET

    import numpy as np

    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    if piece is None:
        raise ValueError(f"{path}: no UnstructuredGrid/Piece")
    n_points = int(piece.get("NumberOfPoints"))
    n_cells = int(piece.get("NumberOfCells"))

    def values(array, count):
        dtype = float if array.get("type", "").startswith("Float") else np.int64
        data = np.array((array.text or "").split(), dtype=dtype)
        k = int(array.get("NumberOfComponents", "1"))
        if data.size != count * k:
            raise ValueError(f"{path}: {array.get('Name')}: {data.size} values, "
                             f"{count} x {k} expected")
        return data.reshape(count, k) if k > 1 else data

    points = values(piece.find("Points/DataArray"), n_points)
    cells = {a.get("Name"): a for a in piece.findall("Cells/DataArray")}
    offsets = values(cells["offsets"], n_cells)
    shape = {4: "quads", 8: "hexes"}
    per_cell = int(offsets[0]) if n_cells else 4
    if per_cell not in shape or not np.array_equal(offsets, per_cell * np.arange(1, n_cells + 1)):
        raise ValueError(f"{path}: only quadrilateral or hexahedral cells are supported")
    nodes = values(cells["connectivity"], per_cell * n_cells).reshape(n_cells, per_cell)
    return {"points": points.reshape(n_points, 3), shape[per_cell]: nodes,
            "cells": {a.get("Name"): values(a, n_cells)
                      for a in piece.findall("CellData/DataArray")},
            "point_data": {a.get("Name"): values(a, n_points)
                           for a in piece.findall("PointData/DataArray")}}


def field_snapshots(run_dir):
    """[(t [s], path)] of the runs/<case>/fields_<t>.vtu files of one run, by time."""
    if not os.path.isdir(run_dir):
        return []
    found = []
    for name in os.listdir(run_dir):
        if name.startswith("fields_") and name.endswith(".vtu"):
            try:
                t = float(name[len("fields_"):-len(".vtu")])
            except ValueError:
                continue
            found.append((t, os.path.join(run_dir, name)))
    return sorted(found)
