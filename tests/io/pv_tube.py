"""Check that ParaView draws a tube run's polyline with its Tube filter: pvpython pv_tube.py <tube.xmf> <field>.

Loads the last time step of the collection, applies Extract Surface and the Tube filter (radius 0.01, 12 sides), and prints the input's segments and nodes, the node field's range, and the tube surface's polygons; exits
non-zero if the field is missing or the filter draws nothing.
"""
import sys

from paraview import servermanager
from paraview.simple import ExtractSurface, MergeBlocks, Tube, XDMFReader


def main():
    path, field = sys.argv[1], sys.argv[2]
    reader = XDMFReader(FileNames=[path])
    times = list(reader.TimestepValues)
    merged = MergeBlocks(Input=reader)
    merged.UpdatePipeline(times[-1])
    data = servermanager.Fetch(merged)
    array = data.GetPointData().GetArray(field)
    if array is None or array.GetNumberOfTuples() != data.GetNumberOfPoints():
        print("pv_tube: node field '%s' missing in %s" % (field, path), file=sys.stderr)
        return 1
    # the reader gives an unstructured grid; the Tube filter takes polydata (in the GUI: Extract Surface, then Tube)
    tube = Tube(Input=ExtractSurface(Input=merged), Radius=0.01, NumberofSides=12)
    tube.UpdatePipeline(times[-1])
    surface = servermanager.Fetch(tube)
    polygons = surface.GetNumberOfCells() if surface is not None else 0
    lo, hi = array.GetRange(0)
    print("pv_tube: segments=%d nodes=%d %s min=%.6g max=%.6g tube_cells=%d"
          % (data.GetNumberOfCells(), data.GetNumberOfPoints(), field, lo, hi, polygons))
    return 0 if polygons > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
