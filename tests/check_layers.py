#!/usr/bin/python3
"""Fails on any include that goes up a layer (docs/ARCHITECTURE.md).

Each layer is a folder pair include/rccm/<layer>/, src/<layer>/ and a CMake target that links
only to the layers below it; a header or source of a layer may include headers of its own
layer and of the layers below, never of a layer above. Also checks that every folder is a
known layer and that libconfig is included by the config reader only.
usage: check_layers.py PROJECT_ROOT
"""
import os, re, sys

LAYERS = ["base", "la", "fem", "interface", "contact", "model", "time", "io", "app"]
root = sys.argv[1] if len(sys.argv) > 1 else "."
rank = {name: k for k, name in enumerate(LAYERS)}
errors, checked = [], 0
for top in ("include/rccm", "src"):
    for layer in sorted(os.listdir(os.path.join(root, top))):
        folder = os.path.join(root, top, layer)
        if not os.path.isdir(folder):
            errors.append("%s/%s: a file outside any layer folder" % (top, layer))
            continue
        if layer not in rank:
            errors.append("%s/%s: not a layer (%s)" % (top, layer, ", ".join(LAYERS)))
            continue
        for dirpath, _, names in os.walk(folder):
            for name in sorted(names):
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                checked += 1
                with open(path, encoding="utf-8") as f:
                    for n, line in enumerate(f, 1):
                        m = re.match(r'\s*#\s*include\s*[<"]rccm/([a-z_]+)/', line)
                        if m:
                            other = m.group(1)
                            if other not in rank:
                                errors.append("%s:%d: includes unknown layer '%s'" % (rel, n, other))
                            elif rank[other] > rank[layer]:
                                errors.append("%s:%d: layer '%s' includes '%s', a layer above it" % (rel, n, layer, other))
                        elif re.match(r'\s*#\s*include\s*[<"]rccm/[a-z_]+\.hpp', line):
                            errors.append("%s:%d: includes a header outside the layer folders" % (rel, n))
                        if re.match(r'\s*#\s*include\s*<libconfig', line) and name != "config_reader.cpp":
                            errors.append("%s:%d: only io/config_reader.cpp includes libconfig" % (rel, n))
for e in errors:
    print(e)
print("%d files checked against the layers %s" % (checked, " < ".join(LAYERS)))
print("%d passed, %d failed" % (checked - len({e.split(':')[0] for e in errors}), len({e.split(':')[0] for e in errors})))
sys.exit(1 if errors else 0)
