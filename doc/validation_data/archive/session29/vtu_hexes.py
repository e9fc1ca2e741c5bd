import sys
import xml.etree.ElementTree as ET
import numpy as np
sys.path.insert(0, '/work/main/scripts')
import plot_field as pf

def read_hexes(path):
    """Points, hexahedra (point indices) and point fields of every piece."""
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") == "vtkZLibDataCompressor"
    points, cells, fields, offset = [], [], {}, 0
    for piece in root.iter("Piece"):
        p = pf.vtu_array(piece.find("Points/DataArray"), compressed)
        c = {a.get("Name"): pf.vtu_array(a, compressed).ravel()
             for a in piece.find("Cells")}
        cells.append(c["connectivity"].reshape(-1, 8) + offset)
        points.append(p)
        offset += len(p)
        for a in piece.find("PointData"):
            fields.setdefault(a.get("Name"), []).append(
                pf.vtu_array(a, compressed))
    return (np.vstack(points), np.vstack(cells),
            {k: np.vstack(v) for k, v in fields.items()})


