"""The mechanism of a strength reduction (the last saved step's plastic_strain_increment) lies
on the slope's slip surface: positive, concentrated (its largest value far above the median) and
between the toe and the crest. Usage: check_mechanism.py RESULT.vtu TOE_X CREST_X"""
import re
import sys

text = open(sys.argv[1]).read()
toe, crest = float(sys.argv[2]), float(sys.argv[3])


def array(name):
    m = re.search(r'<DataArray[^>]*Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
    assert m, "no array " + name
    return [float(v) for v in m.group(1).split()]


m = re.search(r"<Points>\s*<DataArray[^>]*>(.*?)</DataArray>", text, re.S)
xyz = [float(v) for v in m.group(1).split()]
connectivity = [int(v) for v in array("connectivity")]
offsets = [int(v) for v in array("offsets")]
increment = array("plastic_strain_increment")
assert len(increment) == len(offsets), (len(increment), len(offsets))
largest = max(range(len(increment)), key=lambda c: increment[c])
start = offsets[largest - 1] if largest > 0 else 0
ids = connectivity[start:offsets[largest]]
cx = sum(xyz[3 * i] for i in ids) / len(ids)
median = sorted(increment)[len(increment) // 2]
print("largest plastic strain increment %.4g at x = %.2f, median %.3g" % (increment[largest], cx, median))
assert increment[largest] > 0, "no plastic strain increment"
assert increment[largest] > 10 * abs(median), "the increment is not concentrated"
assert toe - 1 <= cx <= crest + 1, "the largest increment is not between toe and crest"
