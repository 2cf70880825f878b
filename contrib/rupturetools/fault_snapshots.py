"""The fault surface output of a run (fault.pvd and its fault_NNNNN.vtu
files, as source/output/fault_output.cc writes them): the list of
snapshots, each snapshot's points, cells and arrays, and the checks of
their structure, and the fault's own coordinates. Used by contrib/plot-fault, contrib/plot-rupture and
contrib/sweep."""

import os
import xml.etree.ElementTree as ET

import numpy as np

NOT_RUPTURED = 1e9  # rupture_time written for nodes that never ruptured

# Every point-data array that fault_output.cc writes, with its number of
# components.
VTU_ARRAYS = {
    "slip": 3,
    "slip_velocity": 3,
    "slip_rate": 1,
    "slip_path": 1,
    "friction_coefficient": 1,
    "normal_traction": 1,
    "shear_traction": 3,
    "state": 1,
    "rupture_time": 1,
}


class PlotError(Exception):
    """A problem with the files (or, in the scripts, the options), reported
    without a traceback."""


class SnapshotEntry:
    """One DataSet line of fault.pvd."""

    def __init__(self, time, name, path):
        self.time = time
        self.name = name
        self.path = path


class Snapshot:
    """The contents of one fault_NNNNN.vtu file."""

    def __init__(self, entry, time, points, cells, arrays):
        self.entry = entry
        self.time = time          # TIME field data, or None if absent
        self.points = points      # (n, 3)
        self.cells = cells        # (m, 2) segments or (m, 4) quads
        self.arrays = arrays      # name -> (n,) or (n, components)

    @property
    def dim(self):
        return 2 if self.cells.shape[1] == 2 else 3


def parse_xml(path):
    try:
        return ET.parse(path).getroot()
    except ET.ParseError as e:
        raise PlotError(f"{path} is not a valid XML file ({e})")
    except OSError as e:
        raise PlotError(f"cannot read {path}: {e.strerror}")


def read_collection(directory):
    """The snapshots listed in DIRECTORY/fault.pvd, sorted by time."""
    if not os.path.isdir(directory):
        raise PlotError(f"{directory} is not a directory")
    path = os.path.join(directory, "fault.pvd")
    if not os.path.isfile(path):
        raise PlotError(
            f"{directory} has no fault.pvd: give the output directory of a "
            "run with a fault (Fault/Model = penalty contact) whose "
            "Output/Output interval is not negative")
    root = parse_xml(path)
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise PlotError(f"{path} is not a VTK collection (.pvd) file")
    entries = []
    for dataset in root.iter("DataSet"):
        time, name = dataset.get("timestep"), dataset.get("file")
        if time is None or not name:
            raise PlotError(f"{path}: a DataSet lacks its timestep or file "
                            "attribute")
        try:
            time = float(time)
        except ValueError:
            time = float("nan")
        if not np.isfinite(time):
            raise PlotError(f"{path}: the timestep of {name} is not a "
                            f"number: '{dataset.get('timestep')}'")
        entries.append(SnapshotEntry(time, name, os.path.join(directory,
                                                              name)))
    if not entries:
        raise PlotError(f"{path} lists no snapshots")
    entries.sort(key=lambda e: e.time)  # stable: equal times keep file order
    return entries


def read_data_array(element, path, what, components=None):
    """The values of an ASCII DataArray as a float array of shape (n,) or
    (n, components)."""
    if element is None:
        raise PlotError(f"{path} has no {what}")
    if element.get("format", "ascii") != "ascii":
        raise PlotError(f"{path}: {what} is not in ASCII format (only the "
                        "ASCII files of rupture are supported)")
    try:
        n = int(element.get("NumberOfComponents", "1"))
    except ValueError:
        n = 0
    if n < 1:
        raise PlotError(f"{path}: {what} has a bad NumberOfComponents")
    if components is not None and n != components:
        raise PlotError(f"{path}: {what} has {n} components, expected "
                        f"{components}")
    try:
        values = np.array((element.text or "").split(), dtype=float)
    except ValueError:
        raise PlotError(f"{path}: {what} contains something that is not a "
                        "number")
    if values.size % n:
        raise PlotError(f"{path}: {what} has {values.size} numbers, not a "
                        f"multiple of its {n} components")
    return values.reshape(-1, n) if n > 1 else values


def read_snapshot(entry, required):
    """Read and check the structure of one .vtu file; REQUIRED lists the
    point-data arrays that must be present."""
    path = entry.path
    if not os.path.isfile(path):
        raise PlotError(f"{path}, listed in fault.pvd, does not exist")
    root = parse_xml(path)
    piece = root.find("UnstructuredGrid/Piece")
    if root.tag != "VTKFile" or piece is None:
        raise PlotError(f"{path} is not a VTK UnstructuredGrid (.vtu) file")
    try:
        n_points = int(piece.get("NumberOfPoints"))
        n_cells = int(piece.get("NumberOfCells"))
    except (TypeError, ValueError):
        raise PlotError(f"{path}: NumberOfPoints or NumberOfCells missing or "
                        "not an integer")

    time = None
    for array in root.iterfind("UnstructuredGrid/FieldData/DataArray"):
        if array.get("Name") == "TIME":
            values = read_data_array(array, path, "TIME")
            if values.size != 1:
                raise PlotError(f"{path}: TIME should be one number")
            time = float(values[0])

    points = read_data_array(piece.find("Points/DataArray"), path,
                             "point coordinates", 3)
    if points.shape[0] != n_points:
        raise PlotError(f"{path}: {points.shape[0]} points, but "
                        f"NumberOfPoints = {n_points}")

    cell_arrays = {a.get("Name"): a for a in piece.iterfind("Cells/DataArray")}
    connectivity, offsets, types = (
        read_data_array(cell_arrays.get(name), path, f"cell {name}")
        for name in ("connectivity", "offsets", "types"))
    if offsets.size != n_cells or types.size != n_cells:
        raise PlotError(f"{path}: {offsets.size} cell offsets and "
                        f"{types.size} cell types for NumberOfCells = "
                        f"{n_cells}")
    if n_cells == 0:
        raise PlotError(f"{path}: the fault has no cells")
    if np.all(types == 3):
        corners = 2   # VTK_LINE: 2-D fault
    elif np.all(types == 9):
        corners = 4   # VTK_QUAD: 3-D fault
    else:
        raise PlotError(f"{path}: the cells should be all lines (type 3, "
                        "2-D) or all quadrilaterals (type 9, 3-D)")
    if (connectivity.size != corners * n_cells or
            np.any(offsets != corners * np.arange(1, n_cells + 1))):
        raise PlotError(f"{path}: cell connectivity and offsets do not match "
                        f"{n_cells} cells of {corners} points")
    if np.any(connectivity != np.round(connectivity)) or (
            connectivity.min() < 0 or connectivity.max() >= n_points):
        raise PlotError(f"{path}: the cell connectivity refers to points "
                        f"outside 0..{n_points - 1}")
    cells = connectivity.astype(int).reshape(n_cells, corners)

    arrays = {}
    for array in piece.iterfind("PointData/DataArray"):
        name = array.get("Name")
        values = read_data_array(array, path, f"the array '{name}'",
                                 VTU_ARRAYS.get(name))
        if values.shape[0] != n_points:
            raise PlotError(f"{path}: the array '{name}' has "
                            f"{values.shape[0]} values for {n_points} points")
        arrays[name] = values
    for name in required:
        if name not in arrays:
            raise PlotError(f"{path} has no array '{name}'")
    return Snapshot(entry, time, points, cells, arrays)


def check_snapshot(snapshot, first):
    """The extra consistency checks of --check."""
    path = snapshot.entry.path
    for name in VTU_ARRAYS:
        if name not in snapshot.arrays:
            raise PlotError(f"{path} has no array '{name}'")
    for name, values in [("point coordinates", snapshot.points)] + sorted(
            snapshot.arrays.items()):
        bad = np.count_nonzero(~np.isfinite(values))
        if bad:
            raise PlotError(f"{path}: {name} has non-finite values ({bad})")
    a = snapshot.arrays
    if not np.all(np.isin(a["state"], (0, 1, 2))):
        raise PlotError(f"{path}: 'state' has values other than 0 (stick), "
                        "1 (slip) and 2 (open)")
    if np.any(a["friction_coefficient"] < 0):
        raise PlotError(f"{path}: negative friction coefficient")
    rate = np.linalg.norm(a["slip_velocity"], axis=1)
    if np.any(np.abs(rate - a["slip_rate"]) >
              1e-6 * np.abs(rate).max() + 1e-12):
        raise PlotError(f"{path}: 'slip_rate' differs from the length of "
                        "'slip_velocity'")
    if snapshot.time is None:
        raise PlotError(f"{path} has no TIME field data")
    if abs(snapshot.time - snapshot.entry.time) > 1e-8 * max(
            1.0, abs(snapshot.time)):
        raise PlotError(f"{path}: TIME = {snapshot.time:g} s, but fault.pvd "
                        f"gives {snapshot.entry.time:g} s")
    if first is not None and (
            snapshot.points.shape != first.points.shape or
            snapshot.cells.shape != first.cells.shape or
            np.any(snapshot.cells != first.cells) or
            np.any(np.abs(snapshot.points - first.points) >
                   1e-8 * np.abs(first.points).max() + 1e-12)):
        raise PlotError(f"{path}: the fault nodes or cells differ from those "
                        f"of {first.entry.name}")


class FaultFrame:
    """Along-strike and down-dip coordinates (km) of points on the fault."""

    def __init__(self, points, dim):
        centre = points.mean(axis=0)
        vertical = np.zeros(3)
        vertical[dim - 1] = 1.0
        if dim == 2:
            # the direction of largest spread of the nodes in the x-y plane
            spread = points[:, :2] - centre[:2]
            tangent = np.zeros(3)
            tangent[:2] = np.linalg.svd(spread, full_matrices=False)[2][0]
            if abs(tangent[0]) >= abs(tangent[1]):
                self.strike = tangent * np.sign(tangent[0])
                self.dip = None
            else:
                self.strike = None
                self.dip = tangent * -np.sign(tangent[1])
            self.nonplanar = 0.0
        else:
            spread = points - centre
            singular, axes = np.linalg.svd(spread, full_matrices=False)[1:]
            normal = axes[2]
            self.nonplanar = singular[2] / max(singular[0], 1e-300)
            strike = np.cross(normal, vertical)
            if np.linalg.norm(strike) < 1e-6:
                # a horizontal fault: take x as the strike
                strike = np.array([1.0, 0.0, 0.0])
                strike -= (strike @ normal) * normal
            strike /= np.linalg.norm(strike)
            self.strike = strike * np.sign(strike[np.argmax(np.abs(strike))])
            dip = np.cross(normal, self.strike)
            if dip[2] > 1e-12 or (abs(dip[2]) <= 1e-12 and
                                  dip[np.argmax(np.abs(dip))] < 0):
                dip = -dip
            self.dip = dip / np.linalg.norm(dip)
        # down-dip distance counts from the level where the vertical
        # coordinate is 0, unless the fault is close to horizontal
        self.dip_offset = 0.0
        self.strike_label = "along-strike distance (km)"
        self.dip_label = "down-dip distance (km)"
        if self.dip is not None:
            down = self.dip[dim - 1]
            if abs(down) > 0.05:
                self.dip_offset = centre @ self.dip - centre[dim - 1] / down
                self.dip_label = ("down-dip distance from "
                                  f"{'yz'[dim - 2]} = 0 (km)")

    def along_strike(self, points):
        return points @ self.strike / 1e3

    def down_dip(self, points):
        return (points @ self.dip - self.dip_offset) / 1e3

    def along_fault(self, points):
        """2-D: the one coordinate along the fault, and its axis label."""
        if self.strike is not None:
            return self.along_strike(points), self.strike_label
        return self.down_dip(points), self.dip_label
