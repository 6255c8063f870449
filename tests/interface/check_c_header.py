#!/usr/bin/env python3
"""Keeps fortran_core/capi/sphjet_core.h in step with the Fortran bind(C) code.

gfortran -fc-prototypes prints the C view of every bind(C) type and procedure; this script
compares it, field by field and argument by argument, with the hand-written header, and the
SPH_* status values with sphjet_kinds.f90. Usage: check_c_header.py GFORTRAN SOURCE_DIR MOD_DIR
"""
import re
import subprocess
import sys


def normalise_type(t):
    t = t.replace("const", "").replace("struct", "")
    t = re.sub(r"\s+", "", t)
    return {"long": "int64_t", "long*": "int64_t*", "double*": "double*", "int*": "int*",
            "void*": "void*"}.get(t, t)


def parse_structs(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    structs = {}
    for m in re.finditer(r"typedef struct (\w+)\s*\{(.*?)\}\s*\w+;", text, re.S):
        fields = []
        for line in m.group(2).split(";"):
            line = re.sub(r"/\*.*?\*/", "", line, flags=re.S).strip()
            if not line:
                continue
            mm = re.match(r"(.*?)(\w+)$", line)
            t = normalise_type(mm.group(1))
            # a Fortran c_ptr is void*; the header may give the pointee type
            fields.append(("void*" if t.endswith("*") else t, mm.group(2)))
        structs[m.group(1)] = fields
    return structs


def parse_functions(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    funcs = {}
    for m in re.finditer(r"^\s*([\w\s\*]+?)(sph_\w+)\s*\(([^)]*)\)\s*;", text, re.M):
        ret = m.group(1)
        args = []
        for a in m.group(3).split(","):
            a = a.strip()
            if not a or a == "void":
                continue
            mm = re.match(r"(.*?)(\w+)$", a)
            args.append(normalise_type(mm.group(1)))
        funcs[m.group(2)] = (normalise_type(ret), args)
    return funcs


def main():
    gfortran, src, mod = sys.argv[1:4]
    out = subprocess.run(
        [gfortran, "-fc-prototypes", "-fsyntax-only", "-I", mod, "-J", "/tmp",
         f"{src}/fortran_core/sphjet_types.f90", f"{src}/fortran_core/capi/sphjet_capi.f90"],
        capture_output=True, text=True, check=True).stdout
    header = open(f"{src}/fortran_core/capi/sphjet_core.h").read()
    errors = []
    fs, hs = parse_structs(out), parse_structs(header)
    ff, hf = parse_functions(out), parse_functions(header)
    kinds = open(f"{src}/fortran_core/sphjet_kinds.f90").read()
    fcodes = dict(re.findall(r"(SPH_\w+)\s*=\s*(\d+)", kinds))
    hcodes = dict(re.findall(r"(SPH_\w+)\s*=\s*(\d+)", header))
    # Nothing parsed on either side means the parse failed (another gfortran's output, an
    # edited header layout), not that the two agree.
    for what, found in [("bind(C) structs in gfortran's output", fs), ("structs in the header", hs),
                        ("bind(C) functions in gfortran's output", ff),
                        ("functions in the header", hf), ("SPH_* codes in sphjet_kinds.f90", fcodes),
                        ("SPH_* codes in the header", hcodes)]:
        if not found:
            errors.append(f"no {what} parsed")
    if set(fs) != set(hs):
        errors.append(f"structs differ: only Fortran {sorted(set(fs) - set(hs))}, "
                      f"only header {sorted(set(hs) - set(fs))}")
    for name, fields in fs.items():
        if name in hs and hs[name] != fields:
            errors.append(f"struct {name}: Fortran {fields}\n  header {hs.get(name)}")
    if set(ff) != set(hf):
        errors.append(f"functions differ: only Fortran {set(ff) - set(hf)}, "
                      f"only header {set(hf) - set(ff)}")
    for name in set(ff) & set(hf):
        if ff[name] != hf[name]:
            errors.append(f"{name}: Fortran {ff[name]} header {hf[name]}")
    if fcodes != hcodes:
        errors.append(f"status codes differ: Fortran {fcodes} header {hcodes}")
    print(f"checked {len(fs)} structs, {len(ff)} functions, {len(fcodes)} status codes")
    if errors:
        print("C header out of step with the Fortran:\n" + "\n".join(errors))
        return 1
    print("C header matches the Fortran bind(C) interface")
    return 0


if __name__ == "__main__":
    sys.exit(main())
