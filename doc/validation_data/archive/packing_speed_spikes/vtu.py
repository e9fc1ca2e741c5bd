import re, sys, base64, zlib, numpy as np
def read(fn):
    s = open(fn).read()
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)"(?: Name="([^"]*)")?(?: NumberOfComponents="(\d+)")? format="binary">\s*(\S+)\s*</DataArray>', s):
        typ, name, nc, data = m.groups()
        name = name or 'Points'
        hdr_len = 24  # base64 of 16 bytes
        hdr = np.frombuffer(base64.b64decode(data[:hdr_len]), dtype=np.uint32)
        nb = hdr[0]
        hl = ((4*(3+nb)+2)//3)*4
        hdr = np.frombuffer(base64.b64decode(data[:hl]), dtype=np.uint32)
        raw = base64.b64decode(data[hl:])
        buf = b''; pos = 0
        for c in hdr[3:3+nb]:
            buf += zlib.decompress(raw[pos:pos+c]); pos += c
        dt = {'Float32': np.float32, 'Float64': np.float64, 'Int32': np.int32, 'UInt8': np.uint8, 'Int64': np.int64, 'UInt32': np.uint32}[typ]
        a = np.frombuffer(buf, dtype=dt)
        if nc: a = a.reshape(-1, int(nc))
        out[name] = a
    return out
if __name__ == '__main__':
    d = read(sys.argv[1])
    for k, v in d.items(): print(k, v.shape)
