"""Seeds for fuzz_observations from a plain (uncompressed) rawlog: for each of
vslam's observation classes, a few inputs made of a class byte (0 visual
landmark, 1 landmark created) and the bytes that follow the class name in the
rawlog (version, fields, end mark and some of the next object).

    python3 make_observation_seeds.py PLAIN_RAWLOG OUTPUT_DIR
"""
import sys

data = open(sys.argv[1], "rb").read()
for selector, name in ((0, b"vslam::CObservationVisualLandmark"),
                       (1, b"vslam::CObservationLandmarkCreated")):
    at, found = 0, 0
    while found < 5:
        at = data.find(name, at)
        if at < 0:
            break
        at += len(name)
        short = name.decode().split(":")[-1]
        with open(f"{sys.argv[2]}/{short}_{found}", "wb") as f:
            f.write(bytes([selector]) + data[at:at + 200])
        found += 1
