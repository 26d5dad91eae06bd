# Rewrites an object file and gives it a valid ncc trailer (runtime/ncrt.cpp objectTrailer), so
# a test reaches the checks behind the checksum: --machine=N sets the ELF machine, --abi=N the
# runtime ABI of the program description.
import struct, sys

src, dst = sys.argv[1], sys.argv[2]
data = bytearray(open(src, "rb").read())
if data[-16:-8] == b"NCCSUM1\0":
    data = data[:-16]
for arg in sys.argv[3:]:
    key, value = arg[2:].split("=")
    if key == "machine":
        data[18:20] = struct.pack("<H", int(value))
    elif key == "abi":
        at = data.index(b"NCCPROG1")
        data[at + 16:at + 24] = struct.pack("<Q", int(value))
h = 0xcbf29ce484222325
for b in data:
    h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
open(dst, "wb").write(bytes(data) + b"NCCSUM1\0" + struct.pack("<Q", h))
