#!/usr/bin/env python3
"""tests/png_check.py -- an outside reader for the PNG files photon writes (tests/test_png.c).

usage: python3 tests/png_check.py FILE.png [EXPECTED.rgb]

Reads FILE.png with Python's standard library alone (zlib for the CRC-32 and the
decompression), none of photon's code, and checks what ISO/IEC 15948 (the PNG Second
Edition) asks of an 8-bit RGB file:
  - the 8-byte signature (Sec. 5.2);
  - every chunk's CRC-32 of its type and data (Sec. 5.3, 5.5), by zlib.crc32;
  - IHDR first, 13 bytes: width and height >= 1, bit depth 8, colour type 2 (RGB),
    compression, filter and interlace methods 0 (Sec. 11.2.2);
  - the IDAT chunks one after another (Sec. 5.6), IEND last and empty, nothing after it;
  - the IDATs' data, joined, is one zlib stream (RFC 1950) that zlib decompresses whole,
    which checks its header, its deflate blocks (RFC 1951) and its Adler-32, with no byte
    after its end;
  - height * (1 + 3 * width) bytes, each scanline's filter-type byte 0 (photon uses None).
With EXPECTED.rgb, the pixel bytes (the scanlines without their filter bytes) must equal
that file's bytes. Prints "png_check: ok WIDTHxHEIGHT, N IDAT chunks" and exits 0, or
prints "png_check: FILE: what is wrong" and exits 1.
"""
import struct
import sys
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"


class Bad(Exception):
    """What is wrong with the file."""


def read_chunks(data):
    """The file's chunks as (type, data) pairs, each CRC checked."""
    if data[:8] != SIGNATURE:
        raise Bad("not a PNG signature: %r" % data[:8])
    chunks, at = [], 8
    while at < len(data):
        if at + 12 > len(data):
            raise Bad("a chunk cut short at byte %d" % at)
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if len(body) != length or at + 12 + length > len(data):
            raise Bad("chunk %r at byte %d runs past the end" % (kind, at))
        (crc,) = struct.unpack(">I", data[at + 8 + length:at + 12 + length])
        if zlib.crc32(kind + body) != crc:
            raise Bad("chunk %r at byte %d: CRC %08x, expected %08x"
                      % (kind, at, crc, zlib.crc32(kind + body)))
        chunks.append((kind, body))
        at += 12 + length
    return chunks


def check_order(chunks):
    """IHDR first, then the IDATs together, IEND last; returns IHDR's width and height."""
    kinds = [kind for kind, _ in chunks]
    if not kinds or kinds[0] != b"IHDR" or kinds[-1] != b"IEND" or chunks[-1][1]:
        raise Bad("chunks %r: expected IHDR first and an empty IEND last" % kinds)
    idat = [i for i, kind in enumerate(kinds) if kind == b"IDAT"]
    if not idat or idat != list(range(idat[0], idat[0] + len(idat))):
        raise Bad("chunks %r: expected consecutive IDAT chunks" % kinds)
    ihdr = chunks[0][1]
    if len(ihdr) != 13:
        raise Bad("IHDR of %d bytes, expected 13" % len(ihdr))
    width, height, depth, colour, compression, filtering, interlace = struct.unpack(
        ">IIBBBBB", ihdr)
    if width < 1 or height < 1 or (depth, colour, compression, filtering, interlace) != (
            8, 2, 0, 0, 0):
        raise Bad("IHDR %r: expected width, height >= 1, depth 8, colour type 2, methods 0"
                  % ((width, height, depth, colour, compression, filtering, interlace),))
    return width, height, len(idat)


def pixel_bytes(chunks, width, height):
    """The decompressed scanlines, checked, without their filter bytes."""
    stream = zlib.decompressobj()
    raw = stream.decompress(b"".join(body for kind, body in chunks if kind == b"IDAT"))
    if not stream.eof or stream.unused_data:
        raise Bad("the zlib stream is cut short or followed by %d bytes"
                  % len(stream.unused_data))
    row = 1 + 3 * width
    if len(raw) != height * row:
        raise Bad("%d bytes of scanlines, expected %d" % (len(raw), height * row))
    filters = set(raw[y * row] for y in range(height))
    if filters != {0}:
        raise Bad("filter types %r, expected 0 on every scanline" % sorted(filters))
    return b"".join(raw[y * row + 1:(y + 1) * row] for y in range(height))


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__.splitlines()[2], file=sys.stderr)
        return 2
    try:
        with open(argv[1], "rb") as f:
            chunks = read_chunks(f.read())
        width, height, n_idat = check_order(chunks)
        pixels = pixel_bytes(chunks, width, height)
        if len(argv) == 3:
            with open(argv[2], "rb") as f:
                expected = f.read()
            if pixels != expected:
                first = next((i for i, (a, b) in enumerate(zip(pixels, expected)) if a != b),
                             min(len(pixels), len(expected)))
                raise Bad("pixel bytes differ from %s (%d and %d bytes), first at byte %d"
                          % (argv[2], len(pixels), len(expected), first))
    except (Bad, zlib.error, OSError) as e:
        print("png_check: %s: %s" % (argv[1], e))
        return 1
    print("png_check: ok %dx%d, %d IDAT chunks" % (width, height, n_idat))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
