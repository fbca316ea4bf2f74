"""Check that ParaView reads an XdmfWriter collection: pvpython pv_read.py <collection.xmf> <field> [cell|node].

Loads the last time step, prints the number of cells and points and the min/max of the field (cell-centred by
default, node-centred with "node"; magnitude for vectors) and exits non-zero if the file cannot be read or the
field is missing or empty.
Needs Debian's python3-paraview (provides pvpython).
"""
import sys

from paraview import servermanager
from paraview.simple import MergeBlocks, XDMFReader, Xdmf3ReaderS


def open_reader(path):
    # XDMFReader (ParaView's "XDMF Reader") takes FileNames; Xdmf3ReaderS takes FileName (a list works too).
    try:
        return "XDMFReader", XDMFReader(FileNames=[path])
    except Exception as e:  # pragma: no cover - fallback if the legacy reader is unavailable
        print("XDMFReader failed (%s), trying Xdmf3ReaderS" % e, file=sys.stderr)
        return "Xdmf3ReaderS", Xdmf3ReaderS(FileName=[path])


def main():
    if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[3] not in ("cell", "node")):
        print("usage: pvpython pv_read.py <collection.xmf> <field> [cell|node]", file=sys.stderr)
        return 2
    path, field = sys.argv[1], sys.argv[2]
    center = sys.argv[3] if len(sys.argv) == 4 else "cell"
    name, reader = open_reader(path)
    times = list(reader.TimestepValues)
    if not times:
        print("pv_read: %s has no time steps" % path, file=sys.stderr)
        return 1
    # Update at an explicit time: without one, Xdmf3ReaderS reports no arrays in pvpython.
    merged = MergeBlocks(Input=reader)
    merged.UpdatePipeline(times[-1])
    data = servermanager.Fetch(merged)
    attributes = None if data is None else data.GetPointData() if center == "node" else data.GetCellData()
    array = attributes.GetArray(field) if attributes is not None else None
    ncells = data.GetNumberOfCells() if data is not None else 0
    npoints = data.GetNumberOfPoints() if data is not None else 0
    if array is None or array.GetNumberOfTuples() == 0 or ncells == 0:
        print("pv_read: %s field '%s' missing or empty in %s (reader %s, cells %d)" % (center, field, path, name, ncells),
              file=sys.stderr)
        return 1
    lo, hi = array.GetRange(0 if array.GetNumberOfComponents() == 1 else -1)
    print("pv_read: reader=%s steps=%d time=%g cells=%d points=%d %s %s min=%.17g max=%.17g"
          % (name, len(times), times[-1], ncells, npoints, center, field, lo, hi))
    return 0


if __name__ == "__main__":
    sys.exit(main())
