"""Seeds for fuzz_frontend: textured grey and colour images with a sane
calibration, in the target's input layout (width/4, height/4, channels,
nine doubles fx fy cx cy k1 k2 p1 p2 k3, pixels).

    python3 make_frontend_seeds.py OUTPUT_DIR
"""
import math
import random
import struct
import sys

random.seed(1)
for name, (w, h, ch) in {"grey_160x120": (160, 120, 1), "colour_80x60": (80, 60, 3)}.items():
    waves = [(random.uniform(0.05, 0.6), random.uniform(0.05, 0.6), random.uniform(0, 6.3)) for _ in range(12)]
    pixels = bytearray()
    for y in range(h):
        for x in range(w):
            v = sum(math.sin(a * x + b * y + p) for a, b, p in waves)
            for _ in range(ch):
                pixels.append(max(0, min(255, int(128 + 18 * v))))
    calib = struct.pack("<9d", 0.8 * w, 0.8 * w, w / 2, h / 2, 0.01, 0, 0, 0, 0)
    with open(f"{sys.argv[1]}/{name}", "wb") as f:
        f.write(bytes([w // 4, h // 4, ch]) + calib + bytes(pixels))
