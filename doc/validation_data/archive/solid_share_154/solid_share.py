#!/usr/bin/python3
# solid_share.py FIELDS.vtu: share of the cells (deal.II patches, 8 points each) with solid
# (alpha < 0 at some vertex): the unknowns a solid-only elastic problem would keep.
import base64, re, struct, sys, zlib
import numpy as np
text = open(sys.argv[1], 'rb').read().decode('ascii')
def decode(block):
    block = block.strip()
    n = struct.unpack('<I', base64.b64decode(block[:8])[:4])[0]
    hlen = 4 * ((4 * (3 + n) + 2) // 3)
    header = struct.unpack('<%dI' % (3 + n), base64.b64decode(block[:hlen]))
    data = base64.b64decode(block[hlen:])
    out, pos = b'', 0
    for size in header[3:]:
        out += zlib.decompress(data[pos:pos + size]); pos += size
    return out
tot = solid = cut = 0
for piece in re.finditer(r'<DataArray type="Float32" Name="alpha" format="binary">(.*?)</DataArray>', text, re.S):
    a = np.frombuffer(decode(piece.group(1)), dtype='<f4').reshape(-1, 8)
    tot += len(a); lo = a.min(1); hi = a.max(1)
    solid += np.sum(lo < 0); cut += np.sum((lo < 0) & (hi > 0))
print('cells', tot, 'with solid', solid, '(%.3f)' % (solid / tot), 'cut', cut, '(%.3f)' % (cut / tot))
