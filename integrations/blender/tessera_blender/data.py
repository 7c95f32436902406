# tessera_blender/data.py — reading tessera's files without Blender: the native JSON
# format (docs/format.md) and the element meshes it names (OBJ, ASCII PLY), plus the
# OBJ scenes `tessera scene` writes (one object per element). Standard library only,
# so that it behaves the same in every Blender version and can be used by plain Python.
import json
import math
import os


class TesseraFileError(ValueError):
    """A file that cannot be read as tessera data; the message names the file."""


# -- quaternions, (w, x, y, z) as everywhere in tessera ------------------------------

def quat_normalized(q, where):
    length = math.sqrt(sum(c * c for c in q))
    if not length > 0.0 or not math.isfinite(length):
        raise TesseraFileError(f"{where}: orientation must be a non-zero quaternion [w, x, y, z]")
    return tuple(c / length for c in q)


def quat_rotate(q, v):
    """v rotated by the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    # t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
    tx = 2.0 * (y * v[2] - z * v[1])
    ty = 2.0 * (z * v[0] - x * v[2])
    tz = 2.0 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + (y * tz - z * ty),
            v[1] + w * ty + (z * tx - x * tz),
            v[2] + w * tz + (x * ty - y * tx))


def quat_conjugate(q):
    return (q[0], -q[1], -q[2], -q[3])


def quat_from_angle_z(angle):
    return (math.cos(0.5 * angle), 0.0, 0.0, math.sin(0.5 * angle))


# -- the native JSON format ----------------------------------------------------------

class ElementType:
    """One entry of "types": name (kept exactly), flags, the mesh file (absolute path or
    None), the reference layout (list of 3-tuples, or None when derived), the topology
    and a sheet's columns."""

    def __init__(self, name, rigid=True, floor=False, mesh=None, reference=None, topology="automatic", columns=0):
        self.name = name
        self.rigid = rigid
        self.floor = floor
        self.mesh = mesh
        self.reference = reference
        self.topology = topology  # "automatic", "none", "thread" or "sheet"
        self.columns = columns  # a sheet's grid columns (sample id = row x columns + column)


class Element:
    """One element: index in the file, id, type index, samples (3-tuples; z = 0 in 2D),
    position (the samples' centroid), orientation (w, x, y, z), scale, radius (0 = none),
    free attributes (name -> value), locked; frames: the samples at every frame of an
    animated file (frames[0] is samples), [samples] otherwise."""

    def __init__(self, index, id, type, samples, orientation, scale, radius, attributes, locked, frames=None):
        self.index = index
        self.id = id
        self.type = type
        self.samples = samples
        self.frames = frames or [samples]
        n = len(samples)
        self.position = tuple(sum(p[k] for p in samples) / n for k in range(3))
        self.orientation = orientation
        self.scale = scale
        self.radius = radius
        self.attributes = attributes
        self.locked = locked


class Document:
    """A file's types and elements; times: the frames' time stamps of an animated file
    (docs/format.md, "Animations (frames)"), None for a still one."""

    def __init__(self, path, dimension, types, elements, attribute_names, times=None):
        self.path = path
        self.dimension = dimension
        self.types = types
        self.elements = elements
        self.attribute_names = attribute_names
        self.times = times

    def topology(self, type_index):
        """The type's topology in effect: automatic is none for single-sample elements and
        thread for multi-sample ones (tessera::effective_topology)."""
        t = self.types[type_index].topology
        if t != "automatic":
            return t
        first = next((e for e in self.elements if e.type == type_index), None)
        return "thread" if first is not None and len(first.samples) > 1 else "none"


def _point(value, dimension, where):
    if not isinstance(value, list) or len(value) != dimension or not all(
            isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c) for c in value):
        raise TesseraFileError(f"{where}: expected {dimension} finite numbers")
    return (float(value[0]), float(value[1]), float(value[2]) if dimension == 3 else 0.0)


def _number(value, where):
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        raise TesseraFileError(f"{where}: expected a finite number")
    return float(value)


def load_document(path):
    """Reads a tessera JSON file (an exemplar or a synthesized arrangement).

    Checks what the import needs (format, version, dimension, types, samples) and
    raises TesseraFileError naming the file and the JSON path otherwise; the full
    validation is tessera's own (`tessera::load`)."""
    path = os.path.abspath(path)
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except OSError as e:
        raise TesseraFileError(f"cannot read {path}: {e.strerror or e}") from None
    except json.JSONDecodeError as e:
        raise TesseraFileError(f"{path}: invalid JSON: {e}") from None
    name = os.path.basename(path)
    if not isinstance(doc, dict) or doc.get("format") != "tessera":
        raise TesseraFileError(f"{name}: not a tessera file (\"format\" is not \"tessera\")")
    if doc.get("version") != 1:
        raise TesseraFileError(f"{name}: version {doc.get('version')!r} is not supported (this add-on reads 1)")
    dimension = doc.get("dimension")
    if dimension not in (2, 3):
        raise TesseraFileError(f"{name}: dimension must be 2 or 3")
    base = os.path.dirname(path)

    types = []
    by_name = {}
    for i, t in enumerate(doc.get("types", [])):
        where = f"{name}: types[{i}]"
        if not isinstance(t, dict) or not isinstance(t.get("name"), str) or not t["name"]:
            raise TesseraFileError(f"{where}: a type needs a non-empty \"name\"")
        if t["name"] in by_name:
            raise TesseraFileError(f"{where}: duplicate type name '{t['name']}'")
        mesh = t.get("mesh") or None
        if mesh is not None:
            mesh = os.path.normpath(os.path.join(base, mesh))
        reference = None
        if t.get("reference"):
            reference = [_point(p, dimension, f"{where}.reference[{k}]") for k, p in enumerate(t["reference"])]
        topology = t.get("topology", "automatic")
        if topology not in ("automatic", "none", "thread", "sheet"):
            raise TesseraFileError(f"{where}.topology: expected none, thread or sheet, got {topology!r}")
        columns = t.get("columns", 0)
        if topology == "sheet" and (not isinstance(columns, int) or isinstance(columns, bool) or columns < 2):
            raise TesseraFileError(f"{where}.columns: a sheet needs an integer number of columns >= 2")
        by_name[t["name"]] = len(types)
        types.append(ElementType(t["name"], bool(t.get("rigid", True)), bool(t.get("floor", False)), mesh, reference,
                                 topology, columns))
    declared = bool(types)

    attribute_names = list(doc.get("attributes", []))
    raw = doc.get("elements")
    if not isinstance(raw, list) or not raw:
        raise TesseraFileError(f"{name}: \"elements\" must be a non-empty array")
    times, frames = _read_frames(doc, name, dimension) if "frames" in doc else (None, None)
    elements = []
    for i, e in enumerate(raw):
        where = f"{name}: elements[{i}]"
        if not isinstance(e, dict):
            raise TesseraFileError(f"{where}: expected an object")
        type_name = e.get("type")
        if type_name is None:
            if declared and len(types) == 1:
                type_name = types[0].name
            elif declared:
                raise TesseraFileError(f"{where}: \"type\" is required when several types are declared")
            else:
                type_name = "default"
        if type_name not in by_name:
            if declared:
                raise TesseraFileError(f"{where}: unknown element type '{type_name}'")
            by_name[type_name] = len(types)
            types.append(ElementType(type_name))
        element_frames = None
        if frames is not None:
            for key in ("position", "samples"):
                if key in e:
                    raise TesseraFileError(f"{where}.{key}: not allowed in an animated file "
                                           "(positions and times are in \"frames\")")
            if e.get("id") not in frames:
                raise TesseraFileError(f"{where}: element id {e.get('id')!r} is in no frame "
                                       "(every frame must hold every element)")
            element_frames = frames.pop(e["id"])
            samples = element_frames[0]
        elif ("position" in e) == ("samples" in e):
            raise TesseraFileError(f"{where}: needs exactly one of \"position\" and \"samples\"")
        elif "position" in e:
            samples = [_point(e["position"], dimension, f"{where}.position")]
        else:
            if not isinstance(e["samples"], list) or not e["samples"]:
                raise TesseraFileError(f"{where}.samples: expected a non-empty array of points")
            samples = [_point(p, dimension, f"{where}.samples[{k}]") for k, p in enumerate(e["samples"])]
        if "orientation" in e:
            q = e["orientation"]
            if not isinstance(q, list) or len(q) != 4:
                raise TesseraFileError(f"{where}.orientation: expected [w, x, y, z]")
            orientation = quat_normalized([_number(c, f"{where}.orientation") for c in q], where)
        elif "angle" in e:
            orientation = quat_from_angle_z(_number(e["angle"], f"{where}.angle"))
        else:
            orientation = (1.0, 0.0, 0.0, 0.0)
        scale = _number(e.get("scale", 1.0), f"{where}.scale")
        if not scale > 0.0:
            raise TesseraFileError(f"{where}.scale: must be > 0")
        radius = _number(e.get("radius", 0.0), f"{where}.radius")
        values = e.get("attributes", [])
        if len(values) != len(attribute_names):
            raise TesseraFileError(f"{where}.attributes: expected {len(attribute_names)} values")
        attributes = {n: _number(v, f"{where}.attributes") for n, v in zip(attribute_names, values)}
        element_id = e.get("id", i)
        if not isinstance(element_id, int) or isinstance(element_id, bool) or element_id < 0:
            raise TesseraFileError(f"{where}.id: must be a non-negative integer")
        elements.append(Element(i, element_id, by_name[type_name], samples, orientation, scale, radius,
                                attributes, bool(e.get("locked", False)), element_frames))
    if frames:
        raise TesseraFileError(f"{name}: frames[0]: element id {next(iter(frames))} is not defined in \"elements\"")
    return Document(path, dimension, types, elements, attribute_names, times)


def _read_frames(doc, name, dimension):
    """The time stamps and, by element id, the samples at every frame of an animated file.
    Checks what the import relies on: increasing times, every element in every frame with
    the same number of samples."""
    raw = doc["frames"]
    if not isinstance(raw, list) or not raw:
        raise TesseraFileError(f"{name}: \"frames\" must be a non-empty array")
    times, by_id = [], {}
    for f, frame in enumerate(raw):
        where = f"{name}: frames[{f}]"
        if not isinstance(frame, dict) or not isinstance(frame.get("elements"), list):
            raise TesseraFileError(f"{where}: expected {{\"time\": T, \"elements\": [...]}}")
        time = _number(frame.get("time"), f"{where}.time")
        if times and not time > times[-1]:
            raise TesseraFileError(f"{where}.time: time stamps must strictly increase ({times[-1]}, then {time})")
        times.append(time)
        seen = set()
        for k, e in enumerate(frame["elements"]):
            at = f"{where}.elements[{k}]"
            element_id = e.get("id") if isinstance(e, dict) else None
            if not isinstance(element_id, int) or isinstance(element_id, bool):
                raise TesseraFileError(f"{at}.id: a frame element needs the integer id of its element")
            if element_id in seen or (f > 0 and element_id not in by_id):
                raise TesseraFileError(f"{at}: element id {element_id!r} is repeated or not in frames[0]")
            seen.add(element_id)
            if isinstance(e.get("samples"), list) and e["samples"]:
                samples = [_point(p, dimension, f"{at}.samples[{j}]") for j, p in enumerate(e["samples"])]
            else:
                samples = [_point(e.get("position"), dimension, f"{at}.position")]
            trail = by_id.setdefault(element_id, [])
            if trail and len(samples) != len(trail[0]):
                raise TesseraFileError(f"{at}: element id {element_id} has {len(samples)} samples here but "
                                       f"{len(trail[0])} in frames[0]")
            trail.append(samples)
        if len(seen) != len(by_id):
            raise TesseraFileError(f"{where}: an element of frames[0] is missing (every frame must hold the same "
                                   "elements)")
    return times, by_id


def derived_reference(element):
    """The layout of an element's samples in its own frame (the inverse of its pose), as
    tessera derives a rigid type's reference from the type's first element."""
    inverse = quat_conjugate(element.orientation)
    c = element.position
    return [tuple(x / element.scale for x in quat_rotate(inverse, (p[0] - c[0], p[1] - c[1], p[2] - c[2])))
            for p in element.samples]


# -- meshes --------------------------------------------------------------------------

def read_mesh(path):
    """Vertices (3-tuples) and faces (tuples of 0-based indices, as many corners as in the
    file) of an OBJ or ASCII PLY mesh; normals, texture coordinates and other
    properties are ignored."""
    ext = os.path.splitext(path)[1].lower()
    if ext == ".obj":
        vertices, objects = _parse_obj(path)
        return vertices, [f for _, _, faces in objects for f in faces]
    if ext == ".ply":
        return _read_ply(path)
    raise TesseraFileError(f"{path}: a mesh is .obj or .ply (ASCII)")


def read_obj_objects(path):
    """The objects (`o` lines) of an OBJ scene as `tessera scene` writes it, in order:
    (name, vertices, faces), each object's faces indexing its own vertices (0-based)."""
    vertices, objects = _parse_obj(path)
    result = []
    for k, (name, first, faces) in enumerate(objects):
        end = objects[k + 1][1] if k + 1 < len(objects) else len(vertices)
        if any(i < first or i >= end for f in faces for i in f):
            raise TesseraFileError(f"{path}: object '{name}' has faces using another object's vertices")
        result.append((name, vertices[first:end], [tuple(i - first for i in f) for f in faces]))
    return result


def _read_text(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return f.read()
    except OSError as e:
        raise TesseraFileError(f"cannot read {path}: {e.strerror or e}") from None


def _parse_obj(path):
    """All vertices of an OBJ file, and its objects as (name, index of the object's first
    vertex, faces with 0-based global indices); what precedes the first `o` line is an
    object named "". OBJ indices are 1-based; negative ones count back."""
    vertices = []
    objects = []
    current = None
    for number, line in enumerate(_read_text(path).splitlines(), 1):
        tokens = line.split("#", 1)[0].split()
        if not tokens:
            continue
        if tokens[0] == "o":
            current = (" ".join(tokens[1:]), len(vertices), [])
            objects.append(current)
        elif tokens[0] == "v":
            try:
                vertices.append((float(tokens[1]), float(tokens[2]), float(tokens[3])))
            except (IndexError, ValueError):
                raise TesseraFileError(f"{path}:{number}: a vertex needs 3 numbers ('v x y z')") from None
        elif tokens[0] == "f":
            if len(tokens) < 4:
                raise TesseraFileError(f"{path}:{number}: a face needs at least 3 vertices")
            face = []
            for t in tokens[1:]:
                try:
                    index = int(t.split("/", 1)[0])
                except ValueError:
                    raise TesseraFileError(f"{path}:{number}: '{t}' is not a vertex index") from None
                if index < 0:
                    index += len(vertices) + 1
                if not 1 <= index <= len(vertices):
                    raise TesseraFileError(f"{path}:{number}: vertex index {t} is out of range")
                face.append(index - 1)
            if current is None:
                current = ("", 0, [])
                objects.append(current)
            current[2].append(tuple(face))
    return vertices, objects


def _read_ply(path):
    lines = _read_text(path).splitlines()
    if not lines or lines[0].strip() != "ply":
        raise TesseraFileError(f"{path}: not a PLY file (no 'ply' magic)")
    elements = []  # [name, count, properties, list property index]
    ascii_format = False
    at = 1
    while True:
        if at >= len(lines):
            raise TesseraFileError(f"{path}: the header has no 'end_header'")
        tokens = lines[at].split()
        at += 1
        if not tokens or tokens[0] in ("comment", "obj_info"):
            continue
        if tokens[0] == "end_header":
            break
        if tokens[0] == "format":
            if len(tokens) < 2 or tokens[1] != "ascii":
                raise TesseraFileError(f"{path}: only ASCII PLY meshes are read; convert it to ascii")
            ascii_format = True
        elif tokens[0] == "element":
            if len(tokens) != 3 or not tokens[2].isdigit():
                raise TesseraFileError(f"{path}: malformed element line {lines[at - 1]!r}")
            elements.append([tokens[1], int(tokens[2]), [], -1])
        elif tokens[0] == "property" and elements:
            if len(tokens) >= 5 and tokens[1] == "list":
                elements[-1][3] = len(elements[-1][2])
            elements[-1][2].append(tokens[-1])
    if not ascii_format:
        raise TesseraFileError(f"{path}: the header has no 'format ascii 1.0' line")
    data = (line.split() for line in lines[at:])
    data = (t for t in data if t)
    vertices, faces = [], []
    for name, count, properties, list_at in elements:
        for _ in range(count):
            try:
                tokens = next(data)
            except StopIteration:
                raise TesseraFileError(f"{path}: the file ends inside element {name}") from None
            if name == "vertex":
                try:
                    vertices.append(tuple(float(tokens[properties.index(c)]) for c in "xyz"))
                except (ValueError, IndexError):
                    raise TesseraFileError(f"{path}: a vertex needs x, y and z") from None
            elif name == "face" and list_at >= 0:
                try:
                    n = int(tokens[list_at])
                    face = tuple(int(i) for i in tokens[list_at + 1:list_at + 1 + n])
                except (ValueError, IndexError):
                    face = ()
                if len(face) < 3 or len(face) != n:
                    raise TesseraFileError(f"{path}: malformed face {' '.join(tokens)!r}")
                faces.append(face)
    if any(i < 0 or i >= len(vertices) for f in faces for i in f):
        raise TesseraFileError(f"{path}: a face indexes a vertex that does not exist")
    return vertices, faces
