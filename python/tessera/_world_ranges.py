"""The `tiles` argument of tessera.world.build and build_local: boxes of tile coordinates with
exclusive ends, as in range() and in the CLI's ``tessera world --tiles X0:X1,Y0:Y1``.

A box is ((x0, x1), (y0, y1)) in 2D or ((x0, x1), (y0, y1), (z0, z1)) in 3D, holding the tiles
x0 <= x < x1 (and so on), or the same as the text "X0:X1,Y0:Y1[,Z0:Z1]". `tiles` is one box
or a list of boxes that do not overlap.
"""

import numbers

from .errors import OptionError

# As the CLI: a larger world is built in several calls (its tiles alone would fill memory).
MAX_TILES = 1 << 22
AXES = "xyz"


def tiles_of(tiles, dimension):
    """The tiles of `tiles` as coordinate tuples, sorted. OptionError naming `tiles` for a
    malformed or empty range, ranges that overlap or more than MAX_TILES tiles."""
    boxes = [_box(item, dimension) for item in _items(tiles)]
    if not boxes:
        raise OptionError("tiles: no range given")
    for a in range(len(boxes)):
        for b in range(a + 1, len(boxes)):
            if all(lo_a < hi_b and lo_b < hi_a for (lo_a, hi_a), (lo_b, hi_b) in zip(boxes[a], boxes[b])):
                raise OptionError("tiles: the ranges %s and %s overlap" % (_text(boxes[a]), _text(boxes[b])))
    count = sum(_count(box) for box in boxes)
    if count > MAX_TILES:
        raise OptionError("tiles: %d tiles, more than %d; build a large world in several calls" % (count, MAX_TILES))
    return sorted(coord for box in boxes for coord in _coords(box))


def _items(tiles):
    """One box, or the boxes of a list."""
    if isinstance(tiles, str) or _looks_like_box(tiles):
        return [tiles]
    if isinstance(tiles, (list, tuple)):
        return list(tiles)
    raise OptionError("tiles must be a box ((x0, x1), (y0, y1)[, (z0, z1)]), its text 'X0:X1,Y0:Y1[,Z0:Z1]' "
                      "or a list of boxes, got %r" % (tiles,))


def _looks_like_box(value):
    return (isinstance(value, (list, tuple)) and len(value) > 0 and
            all(isinstance(pair, (list, tuple)) and len(pair) == 2 and all(_is_integer(v) for v in pair)
                for pair in value))


def _is_integer(value):
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def _box(item, dimension):
    """((lo, hi), ...) per axis, checked."""
    form = "((x0, x1), (y0, y1))" if dimension == 2 else "((x0, x1), (y0, y1), (z0, z1))"
    text_form = "X0:X1,Y0:Y1" if dimension == 2 else "X0:X1,Y0:Y1,Z0:Z1"
    pairs = _parse_text(item) if isinstance(item, str) else item
    if not _looks_like_box(pairs) or len(pairs) != dimension:
        raise OptionError("tiles: a %dD world's tiles are given as %s or '%s' with integer ends, the ends "
                          "exclusive, got %r"
                          % (dimension, form, text_form, item))
    box = tuple((int(lo), int(hi)) for lo, hi in pairs)
    for axis, (lo, hi) in zip(AXES, box):
        if hi <= lo:
            raise OptionError("tiles: the range %d:%d along %s holds no tile (ends are exclusive, as in range())"
                              % (lo, hi, axis))
    return box


def _parse_text(text):
    """'0:4,0:3' -> ((0, 4), (0, 3)); None when it is not of that form (the caller says what is)."""
    pairs = []
    for part in text.split(","):
        ends = part.strip().split(":")
        try:
            pairs.append(tuple(int(end) for end in ends))
        except ValueError:
            return None
    return pairs if all(len(pair) == 2 for pair in pairs) else None


def _count(box):
    count = 1
    for lo, hi in box:
        count *= hi - lo
    return count


def _coords(box):
    if len(box) == 2:
        return ((x, y) for x in range(*box[0]) for y in range(*box[1]))
    return ((x, y, z) for x in range(*box[0]) for y in range(*box[1]) for z in range(*box[2]))


def _text(box):
    return ",".join("%d:%d" % pair for pair in box)
