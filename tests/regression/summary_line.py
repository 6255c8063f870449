"""The SUMMARY line that analysis tools print (tools/axisymmetric.py, `sphjet drop`):
`SUMMARY key=value ...` -> dict, numbers as floats; None when there is no such line."""


def summary(text):
    for line in text.splitlines():
        if line.startswith("SUMMARY "):
            out = {}
            for item in line.split()[1:]:
                k, _, v = item.partition("=")
                try:
                    out[k] = float(v)
                except ValueError:
                    out[k] = v
            return out
    return None
