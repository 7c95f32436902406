"""tessera: synthesize arrangements of discrete elements from a small example.

Give tessera a few dozen placed elements (an *exemplar*: pebbles, trees and the
mushrooms in their shade, noodles, ...) and an output domain; it fills the domain
with elements whose local arrangement looks like the exemplar's everywhere.

    import numpy as np, tessera
    ex = tessera.exemplar(points, classes=labels, class_names=["tree", "bush"],
                          domain=tessera.Domain.box((0, 0), (10, 10)))
    out = tessera.synthesize(ex, domain="box:40,40", seed=7)
    tessera.save(out, "forest.usda")

or grow one on demand, next to what exists, with :class:`Grower`, or synthesize an
animation from an animated exemplar (:class:`Animation`, :func:`animation`,
``synthesize(..., method="dynamic")``).

Data travel as numpy arrays (see :class:`Exemplar`) or as files (:func:`load`,
:func:`save`; formats by extension as in the CLI, docs/format.md). Options of
:func:`synthesize` have the names and defaults of ``tessera synth``'s flags, with
dashes written as underscores (``--patch-size`` -> ``patch_size``; ``--lambda`` ->
``lambda_``). Errors are raised as :class:`TesseraError` subclasses carrying the
library's message (``OptionError`` and ``InputError`` are ``ValueError``\\ s).
The library releases the GIL while it works, so other Python threads keep running
and several syntheses may run at once from different threads.
"""

import json as _json
import numbers as _numbers
import os as _os

from . import _options, _tessera
from ._tessera import AnimatedArrangement, Animation, Arrangement, Domain, Exemplar, PcfModel
from .errors import (Cancelled, DomainError, FileError, InputError, InternalError, OptionError,
                     TesseraError)
from . import world  # tessera.world: unbounded worlds of deterministic tiles

__version__ = _tessera.version
__all__ = [
    "AnimatedArrangement", "Animation", "Arrangement", "BrushCanvas", "Cancelled", "Domain", "DomainError",
    "Exemplar", "FileError", "Grower", "InputError", "InternalError", "OptionError", "PcfModel", "TesseraError",
    "analyze", "animate", "animation", "brush", "decompose", "exemplar", "load", "load_animation", "metrics", "pair_correlation",
    "recombine", "render", "save", "save_animation", "synthesize",
]

# The methods of synthesize, each with its option table.
_SYNTH_METHODS = ("det", "pcf", "dynamic")


def exemplar(positions, classes=None, class_names=None, radii=None, orientations=None, scales=None,
             ids=None, locked=None, element_of_sample=None, sample_ids=None, times=None,
             attributes=None, attribute_names=None, domain=None, types=None):
    """Build an exemplar from numpy arrays.

    positions          S x 2 or S x 3 sample positions (one row per element when every
                       element is a single sample).
    element_of_sample  S element indices 0, 1, 2, ... with each element's samples in one
                       run; default: every sample is its own element.
    sample_ids         S positions within the element (0, 1, ...); only checked.
    times              S time stamps (default 0).
    classes            E class indices into class_names (default all 0).
    class_names        names of the classes (default "0", "1", ...).
    radii, scales      E radii (default 0 = none) and uniform scales (default 1).
    orientations       E x 4 unit quaternions (w, x, y, z); default identity.
    ids                E unique uint64 element ids (default 0 .. E-1).
    locked             E booleans: locked elements are never moved.
    attributes         E x A free attributes named by attribute_names.
    domain             a Domain (or (lo, hi) corners) the elements were observed in;
                       default the bounding box of the positions.
    types              optional list of dicts per class: {"name", "rigid", "floor", "mesh",
                       "color", "reference", "depends_on"} (docs/format.md, "Element types");
                       "color" is "#rrggbb" or a colour name, the class's colour in pictures.

    Raises OptionError (a ValueError) naming the array with the wrong shape or value,
    InputError when the data break the model's invariants.
    """
    return _tessera.make_exemplar(positions, classes, class_names, radii, orientations, scales, ids,
                                  locked, element_of_sample, sample_ids, times, attributes,
                                  attribute_names, _as_domain(domain, None, 2.0, "domain"), types)


def load(path, input_domain=None):
    """Load an exemplar or a previous output from a .json (tessera's native format) or
    .csv table (docs/format.md). input_domain: the observation window of a CSV file (a
    Domain or (lo, hi) corners; default the points' bounding box). A file with frames gives
    its frame 0 (load_animation reads them all)."""
    return _tessera.load(_os.fspath(path), _as_domain(input_domain, None, 2.0, "input_domain"))


def animation(exemplar, positions, times=None):
    """Build an Animation (elements in space and time) from an exemplar and numpy arrays.

    exemplar   the elements: an Exemplar (classes, radii, ids, ...; its domain is the
               animation's) or a path to one. Its own positions are not used.
    positions  F x S x d: the positions of the exemplar's S samples (in its sample order) in
               each of F frames; d is the exemplar's dimension.
    times      F strictly increasing time stamps; default 0, 1, ..., F-1.

    Raises OptionError (a ValueError) naming the array with the wrong shape, InputError
    when the data break the model (time stamps that do not increase, NaN positions).
    """
    exemplar = _as_data(exemplar)
    if not isinstance(exemplar, Exemplar):
        raise OptionError("exemplar must be a tessera.Exemplar or a file path, got %s" % type(exemplar).__name__)
    return _tessera.make_animation(exemplar, positions, times)


def load_animation(path, input_domain=None):
    """Load an Animation from .json or .csv (docs/format.md, "Animations (frames)"); a file
    without frames gives a one-frame animation. input_domain as for load."""
    return _tessera.load_animation(_os.fspath(path), _as_domain(input_domain, None, 2.0, "input_domain"))


def save_animation(animation, path):
    """Write an Animation, chosen by the extension of path, atomically: .json (with the run
    statistics of an AnimatedArrangement), .csv (one row per sample per frame), .usda (a USD
    layer whose instancer poses are time samples, one per frame), or .png: an
    animated PNG with each particle's path over the last 6 frames drawn behind it (as
    `tessera synth -o clip.png` writes it)."""
    if not isinstance(animation, Animation):
        raise OptionError("animation must be a tessera.Animation, got %s" % type(animation).__name__)
    _tessera.save_animation(animation, _os.fspath(path))


def decompose(animation, **options):
    """Split an Animation into its coarse motion and its details (`tessera analyze
    --decompose`; Dynamic Element Textures, section 5): returns (coarse, detail), two
    Animations with the input's elements and times. coarse is a low-pass filter of the
    samples' positions in space and time (a separable Gaussian whose window shrinks
    symmetrically near the first and last frames, the ends of threads and sheets, and for
    particles the domain's bounding box); detail holds the offsets input - coarse, so that
    recombine(coarse, detail) gives the input back. animation may be a path to a file with
    frames. See docs/dynamic.md, "Analysis: coarse and detail motion"."""
    _options.check_keywords("decompose", options, ("low_pass",))
    return _tessera.decompose_motion(_as_animation(animation, "animation"), options)


_options.with_signature(decompose, ("animation",), ("low_pass",))


def recombine(coarse, detail):
    """The coarse motion of one animation with the details of another (`tessera recombine`):
    coarse + detail, an Animation with coarse's elements and times. Frame f takes detail frame
    f mod its frame count; the i-th element of a kind (particle, thread, sheet) takes the
    detail's (i mod its count)-th element of that kind; threads and sheets of another sample
    count are resampled linearly along their index. Either may be a path. InputError when the
    detail has no element of a kind coarse has, or another dimension."""
    return _tessera.recombine_motion(_as_animation(coarse, "coarse"), _as_animation(detail, "detail"))


def animate(still, **options):
    """Motion for a still by graph synthesis (`tessera animate`; Dynamic Element Textures,
    section 4.3): an Animation of `frames` frames whose frame 0 is the still. Particles walk
    annealed paths through the graph of the still's neighbourhoods; threads, sheets and rigid
    multi-sample elements through the graph of its element shapes, their centroids as
    particles, threads and sheets held to their rest lengths and apart, rigid elements turned
    only. still may also be a short clip (an Animation, or a path to a file with frames):
    its frames come first, and it is continued from its last frame through the neighbourhoods
    of all its frames (a clip of `frames` frames or more is returned as it is). See
    docs/dynamic.md, "Graph synthesis (motion from a still)"."""
    _options.check_keywords("animate", options, ("graph_motion",))
    if isinstance(still, Exemplar):
        return _tessera.enrich_by_graph(still, options)
    return _tessera.extend_by_graph(_as_animation(still, "still"), options)


_options.with_signature(animate, ("still",), ("graph_motion",))


def _as_animation(data, name):
    if isinstance(data, (str, bytes, _os.PathLike)):
        return load_animation(data)
    if not isinstance(data, Animation):
        raise OptionError("%s must be a tessera.Animation or a file path, got %s" % (name, type(data).__name__))
    return data


def save(data, path, *, gltf_instancing="gpu"):
    """Write an exemplar or arrangement, chosen by the extension of path, atomically (a
    failed call leaves no file). docs/format.md describes each format:
      .json   tessera's native format (with the run statistics of an Arrangement)
      .csv    one row per sample
      .ply    one point per element with Houdini's attribute names (P, orient, pscale,
              class, id, radius, the free attributes)
      .usda   a USD layer: a UsdGeomPointInstancer whose prototypes are the element types'
              meshes (default shapes for types without one)
      .gltf / .glb  glTF 2.0; gltf_instancing="gpu" instances each shared mesh with
              EXT_mesh_gpu_instancing, "nodes" writes one node per element (for viewers
              without the extension, Blender 3.4 among them)
      .obj / .mesh.ply  the elements' triangle meshes
      .png / .svg  a preview picture
    An Animation is written by save_animation (.json, .csv, .png)."""
    if isinstance(data, Animation):
        return save_animation(data, path)
    _tessera.save(data, _os.fspath(path), gltf_instancing)


def render(data, path, width=800, meshes="auto", legend=True):
    """Write a preview picture (.png or .svg) of an exemplar or arrangement: disks and
    polylines by class in 2D, a shaded orthographic view in 3D, each class in its colour
    (its type's "color", else its name when that is a colour, else a palette). meshes:
    "auto" draws the element types' meshes when some type has one, "on" always, "off"
    never. legend: a strip below the picture with a swatch and the name of every class
    (never for a single unnamed class)."""
    _tessera.render(data, _os.fspath(path), width, meshes, bool(legend))


def synthesize(exemplar, domain=None, *, scale=2.0, method="det", coarse=None, progress=None, **options):
    """Synthesize an arrangement like `exemplar` that fills `domain`; returns an Arrangement
    (an AnimatedArrangement for method="dynamic").

    exemplar  an Exemplar (from tessera.exemplar or tessera.load), an Animation (from
              tessera.animation or tessera.load_animation), a path to either, or, for
              method="pcf", an analysed PcfModel (then `domain` is required).
    domain    the output domain: a Domain; (lo, hi) corners; a string in the CLI's --domain
              forms ("box:W,H[,D]" from the exemplar's lower corner, "box:xmin,ymin,xmax,ymax",
              "polygon:FILE.json", "mask:FILE.png[@box]", "mesh:FILE[,res]", "shell:FILE,t[,res]");
              or None: the exemplar's domain scaled by `scale` (2 = about 4x the elements in 2D);
              for an Animation, that of its frame 0.
    method    "det": neighbourhood matching (Discrete Element Textures; 2D and 3D, any elements);
              "pcf": 2D disks from pair correlation functions (multi-class, dependent classes);
              "dynamic": an animation (Dynamic Element Textures) of single-sample elements,
              frame by frame, like an animated exemplar.
              An Animation, or a path to a file with frames, is synthesized by "dynamic" when
              method is left at "det" (as `tessera synth` picks it); pass its frame 0
              (animation.exemplar, tessera.load(path)) for a static method. An Exemplar given
              with method="dynamic" is a one-frame animation, given motion by graph synthesis
              first (graph_frames; docs/dynamic.md, "Graph synthesis").
    coarse    method "dynamic" only: an Animation (or a path to a file with frames) giving the
              output's elements (threads, sheets or particles) and their coarse motion; the
              exemplar's detail motion is laid on it, all frames together (docs/dynamic.md,
              "Threads and sheets on a coarse motion"). The output has its elements and frames;
              domain and scale do not apply.
    progress  optional callable, called with a dict (stage, iteration, iterations, energy,
              elapsed, fraction) for every event of the run: its stages (det: "init",
              "patches", "fill", "iteration", "relax", "repair", "settle" with physics;
              pcf: "analysis", "init", "iteration", "repair"; dynamic: "first frame",
              "frame") with their step iteration / iterations where they have one, and the
              end ("done"); fraction is the share of the whole run done, 0 to 1 (1 at
              "done"); the same events the CLI prints. Return False to cancel
              (tessera.Cancelled is raised); an exception it raises cancels the run and
              propagates.

    The options of the methods (listed below, from the library's option tables; the same
    names, defaults and checks as `tessera synth`'s flags, dashes written as underscores):
    seed (the same inputs, options and seed give identical output whatever `threads` is),
    iterations (default 10 for det, 100 for pcf, 2 for dynamic), threads and others are
    shared; the rest belong to one method. None keeps an option's default.
    An option only other methods have, set to a value other than their default, is an
    OptionError.

    Raises OptionError/DomainError/InputError (ValueErrors) naming what is wrong, FileError,
    Cancelled. The GIL is released while the library works.
    """
    method = _method_for(exemplar, method)
    if isinstance(exemplar, Animation) and method != "dynamic":
        raise OptionError("an Animation is synthesized with method='dynamic'; pass animation.exemplar (its frame 0) "
                          "for method=%r" % (method,))
    options = _options.of_method("synthesize", method, _SYNTH_METHODS, options)
    if progress is not None and not callable(progress):
        raise OptionError("progress must be callable, got %r" % (progress,))
    if coarse is not None:
        return _synthesize_on_coarse(exemplar, domain, method, coarse, options, progress)
    if method == "dynamic":
        return _synthesize_dynamic(exemplar, domain, scale, options, progress)
    if isinstance(exemplar, (str, bytes, _os.PathLike)):
        exemplar = load(exemplar)
    if isinstance(exemplar, PcfModel):
        if method != "pcf":
            raise OptionError("a PcfModel is synthesized with method='pcf'")
        if domain is None:
            raise OptionError("domain is required when synthesizing from a PcfModel")
        for name in ("sigma", "step", "extent"):
            if options.get(name) is not None:
                raise OptionError("%s is fixed by the analysed model; analyze the exemplar again to change it" % name)
        return _tessera.synthesize_model(exemplar, _as_domain(domain, None, scale, "domain"), options,
                                         progress)
    if not isinstance(exemplar, Exemplar):
        raise OptionError("exemplar must be a tessera.Exemplar, an Animation, a PcfModel or a file path, got %s"
                          % type(exemplar).__name__)
    return _tessera.synthesize(exemplar, _as_domain(domain, exemplar, scale, "domain"), method, options,
                               progress)


def _method_for(exemplar, method):
    """The method a call asks for: the default "det" means "dynamic" for an Animation or a
    path to a file with frames (`tessera synth` picks the method by its input the same way)."""
    if method != "det":
        return method
    if isinstance(exemplar, Animation):
        return "dynamic"
    if isinstance(exemplar, (str, bytes, _os.PathLike)) and _tessera.has_frames(_os.fspath(exemplar)):
        return "dynamic"
    return method


def _synthesize_on_coarse(exemplar, domain, method, coarse, options, progress):
    if method != "dynamic":
        raise OptionError("coarse= belongs to method='dynamic', not %r" % (method,))
    if domain is not None:
        raise OptionError("coarse= gives the output's elements and where they go: domain does not apply")
    if isinstance(exemplar, (str, bytes, _os.PathLike)):
        exemplar = load_animation(exemplar)
    if isinstance(coarse, (str, bytes, _os.PathLike)):
        coarse = load_animation(coarse)
    if not isinstance(exemplar, Animation) or not isinstance(coarse, Animation):
        raise OptionError("exemplar and coarse must be tessera.Animations or file paths with frames")
    return _tessera.synthesize_on_coarse(exemplar, coarse, options, progress)


def _synthesize_dynamic(exemplar, domain, scale, options, progress):
    if isinstance(exemplar, (str, bytes, _os.PathLike)):
        exemplar = load_animation(exemplar)
    elif isinstance(exemplar, Exemplar):
        exemplar = _tessera.animation_from_exemplar(exemplar)
    if not isinstance(exemplar, Animation):
        raise OptionError("exemplar must be a tessera.Animation, an Exemplar or a file path for method='dynamic', "
                          "got %s" % type(exemplar).__name__)
    return _tessera.synthesize_dynamic(exemplar, _as_domain(domain, exemplar.exemplar, scale, "domain"), options,
                                       progress)


_options.with_signature(synthesize, ("exemplar", "domain", "scale", "method", "coarse"), _SYNTH_METHODS, ("progress",))


class Grower(_tessera.Grower):
    """On-demand growth (`tessera grow`): an arrangement grown outward along its horizon,
    next to elements that already exist and never move, for when the output domain is not
    known in advance (a game world, a brush).

        g = tessera.Grower(ex, seed=3)
        g.grow(ex.domain.scaled(2.0))      # until the region takes no more elements
        g.grow(200)                        # then about 200 more, outward
        out = g.arrangement

    exemplar  an Exemplar (from tessera.exemplar or tessera.load) or a path to one.
    options   the keywords listed in help(tessera.Grower.__init__), from the library's
              option table, with the names, defaults and checks of `tessera grow`'s flags:
              seed (the same exemplar, options and seed give the same arrangement whatever
              `threads` is), choice ("patch": copy the input patch that fits best at each
              horizon element, then filter; "mcts": the paper's single-player Monte-Carlo
              tree search, with playouts, explore, exploit), radius, patch_extent, threshold,
              energy_factor, lock_distance, band_weight, solves, votes, k, alpha, max_rounds,
              field (an orientation field in the --field forms, "vortex:5,5").

    Methods: seed(center), set_arrangement(arrangement), grow(region) / grow(n), step();
    each grow call returns a report dict (rounds, added, candidates, merged, high_energy,
    outside, reassigned, last_made, displaced, filled, covered, bound_hit, energy, seconds).
    Properties: arrangement (an Arrangement), locked (E booleans), horizon (indices of the
    current horizon's elements), radius (the radius in use), last_report (the report of the
    last call, also of a cancelled one), len(grower).

    Raises OptionError naming the keyword (``energy_factor must be a number > 1, got
    0.5``), InputError for an invalid exemplar. The GIL is released while it grows; a
    Grower serves one thread at a time (RuntimeError when another thread is using it).
    """

    def __init__(self, exemplar, **options):
        _options.check_keywords("Grower", options, ("grow",))
        exemplar = _as_data(exemplar)
        if not isinstance(exemplar, Exemplar):
            raise OptionError("exemplar must be a tessera.Exemplar or a file path, got %s"
                              % type(exemplar).__name__)
        super().__init__(exemplar, options)
        # Text-form regions ("box:W,H") are relative to the exemplar, as for `tessera grow`.
        self._exemplar = exemplar

    _options.with_signature(__init__, ("self", "exemplar"), ("grow",))

    def set_arrangement(self, arrangement):
        """Start over from `arrangement` (an Arrangement or Exemplar, or a path to one), whose
        types are matched to the exemplar's by name: its elements become locked (they never
        move, change type or go) and are the first horizon. InputError for an unknown type
        or a different sample count."""
        arrangement = _as_data(arrangement)
        if not isinstance(arrangement, Exemplar):
            raise OptionError("arrangement must be a tessera.Arrangement, an Exemplar or a file path, got %s"
                              % type(arrangement).__name__)
        super().set_arrangement(arrangement)

    def grow(self, target, *, progress=None):
        """grow(region): grow until `region` takes no more elements (candidates outside it are
        dropped); region is a Domain, (lo, hi) corners or a --region text form relative to the
        exemplar ("box:W,H", "polygon:FILE.json", ...). An empty arrangement starts from an
        exemplar patch at the region's centre; otherwise the region must touch it.
        grow(n): grow by about n elements (n > 0), outward from the arrangement.

        progress  optional callable, called with a dict (stage, iteration, iterations, energy,
                  elapsed, fraction) at the start ("round", iteration -1), after each round
                  ("round") and at the end ("done"), between rounds. Return False to cancel
                  (tessera.Cancelled); an exception it raises cancels and propagates. The
                  rounds done before a cancel stay in the arrangement.

        Returns the report dict. Raises OptionError for n <= 0, DomainError for an empty region
        or one of the wrong dimension, InputError for a region that does not touch the
        arrangement. The GIL is released while it grows."""
        if progress is not None and not callable(progress):
            raise OptionError("progress must be callable, got %r" % (progress,))
        if isinstance(target, _numbers.Integral) and not isinstance(target, bool):
            return super().grow(int(target), progress)
        if target is None or isinstance(target, bool):
            raise OptionError("grow needs a region or a number of elements n, got %r" % (target,))
        if isinstance(target, str):
            return super().grow(_tessera.parse_region(target, self._exemplar), progress)
        return super().grow(_as_domain(target, None, 1.0, "region"), progress)

    def __repr__(self):
        return "<tessera.Grower %dD, %d elements, radius %.4g>" % (self._exemplar.dimension, len(self),
                                                                   self.radius)


class BrushCanvas(_tessera.BrushCanvas):
    """Brushing element fields (`tessera brush`, docs/brush.md): a canvas painted with elements
    of one or several exemplars along strokes, with direction strokes that set the element
    field where you want it, erase strokes, and fill() that completes the rest.

        c = tessera.BrushCanvas(((0, 0), (40, 30)), seed=3)
        c.add_exemplar("sticks", "examples/sticks_2d.json")
        c.paint("sticks", [(2, 5), (20, 16), (38, 5)], width=4)   # grown along the stroke, locked
        c.direct([(5, 25), (35, 25)])                            # the field there
        c.fill()                                                 # the rest, along the field
        out = c.arrangement

    domain    a Domain, or (lo, hi) corners: a 2D plane region or a 3D volume.
    options   the keywords listed in help(tessera.BrushCanvas.__init__), from the library's
              option table, with the names, defaults and checks of `tessera brush`'s flags.

    Palette entries are named; paint, fill take names (fill: one name, a list, or none for
    the entries already on the canvas). Strokes are sequences of 2D or 3D points. Calls return
    a report dict (added, removed, iterations, lbfgs_bound_hits, solve_bound_hits,
    kept_earlier, energy, seconds); progress callables are called as for Grower.
    Properties: arrangement, sample_directions (S x dim, the orientation o(s) of each sample),
    sample_exemplars (S palette indices), palette (names), energies (dict per term).
    """

    def __init__(self, domain, **options):
        _options.check_keywords("BrushCanvas", options, ("brush",))
        super().__init__(_as_domain(domain, None, 1.0, "domain"), options)

    _options.with_signature(__init__, ("self", "domain"), ("brush",))

    def add_exemplar(self, name, exemplar):
        """Adds an exemplar (an Exemplar or a path to one) to the palette under `name`."""
        exemplar = _as_data(exemplar)
        if not isinstance(exemplar, Exemplar):
            raise OptionError("exemplar must be a tessera.Exemplar or a file path, got %s" % type(exemplar).__name__)
        return super().add_exemplar(str(name), exemplar)

    def _entry(self, name):
        k = self.find_exemplar(str(name))
        if k < 0:
            raise OptionError("no palette entry named %r (the palette: %s)" % (name, ", ".join(self.palette)))
        return k

    def paint(self, entry, stroke, *, width=0.0, progress=None):
        """Grows elements of palette entry `entry` along `stroke`, in a band `width` wide
        (0 = stroke_width spacings), oriented along it; they are locked."""
        return super().paint(self._entry(entry), stroke, float(width), progress)

    def direct(self, stroke):
        """A direction stroke: the element field follows it near the stroke (Eq. 5)."""
        return super().direct(stroke)

    def erase(self, stroke, *, width=0.0):
        """Removes the elements whose centre lies within width / 2 of the stroke."""
        return super().erase(stroke, float(width))

    def fill(self, entries=None, *, progress=None):
        """Completes the canvas from the entries already on it (or `entries`: a name or a list
        of names), then runs the solver over every unlocked element."""
        if entries is None:
            names = []
        elif isinstance(entries, str):
            names = [entries]
        else:
            names = list(entries)
        return super().fill([self._entry(n) for n in names], progress)

    def optimize(self, iterations, *, progress=None):
        """The solver alone (section 5) over every unlocked element."""
        return super().optimize(int(iterations), progress)

    def __repr__(self):
        return "<tessera.BrushCanvas %d elements, palette %s>" % (len(self), list(self.palette))


def brush(session, *, progress=None, **options):
    """Replays a brush session file (`tessera brush SESSION`, docs/brush.md) and returns the
    canvas (a _tessera.BrushCanvas with the properties of tessera.BrushCanvas). Options given
    here override the file's "options"."""
    _options.check_keywords("brush", options, ("brush",))
    if progress is not None and not callable(progress):
        raise OptionError("progress must be callable, got %r" % (progress,))
    return _tessera.brush_session(_os.fspath(session), options, progress)


_options.with_signature(brush, ("session",), ("brush",), ("progress",))


def analyze(exemplar, *, sigma=0.25, step=0.1, extent=5.0):
    """Analyse a 2D exemplar for the PCF method (`tessera analyze`): r_max (Eq. 1), the
    mean PCF and validity envelope of each class and each dependency (Eq. 2, 3) on the
    normalised axis (the disk metric of Eq. 7-10 for disks). The dependency graph comes
    from the types' depends_on (default: every class depends on all earlier ones).
    Returns a PcfModel; use tessera.synthesize(model, domain, method="pcf") to synthesize
    from it, model.to_json() / tessera.save_model to keep it, tessera.plot_model to draw it."""
    if isinstance(exemplar, (str, bytes, _os.PathLike)):
        exemplar = load(exemplar)
    return _tessera.analyze(exemplar, sigma, step, extent)


def save_model(model, path):
    """Write a PcfModel as JSON (the format `tessera analyze -o` writes), atomically."""
    _tessera.save_model(model, _os.fspath(path))


def load_model(path):
    """Read a PcfModel written by save_model or `tessera analyze -o`."""
    return _tessera.load_model(_os.fspath(path))


def plot_model(model, path, compare=None):
    """Draw every PCF of a model with its envelope (.png or .svg); with `compare` (an
    arrangement), its measured mean PCFs are drawn over the model's."""
    _tessera.plot_model(model, _os.fspath(path), compare)


def compare_model(model, exemplar, output):
    """How well `output` reproduces `model` (analysed from `exemplar`): the share of r-bins of
    each PCF inside the validity envelope, the count ratio per class, and the shares of the
    salient disk configurations in input and output (dicts)."""
    return _tessera.compare(model, exemplar, output)


def metrics(exemplar, output, **options):
    """Compare an output with its exemplar (`tessera metrics`): pair correlation per class
    pair in physical units and its relative error, nearest-neighbour distances, |psi6| in 2D.
    Returns the report as a dict. The estimate's options are those of pair_correlation."""
    _options.check_keywords("metrics", options, ("pair_correlation",))
    return _json.loads(_tessera.metrics_report(_as_data(exemplar), _as_data(output), options))


_options.with_signature(metrics, ("exemplar", "output"), ("pair_correlation",))


def pair_correlation(data, **options):
    """The standard pair correlation g(r) of an arrangement (spatstat's convention: Gaussian
    kernel, translation edge correction). Returns (r, curves, bandwidth) where curves maps
    (class_a, class_b) name pairs to arrays of g over r."""
    _options.check_keywords("pair_correlation", options, ("pair_correlation",))
    return _tessera.pair_correlation(_as_data(data), options)


_options.with_signature(pair_correlation, ("data",), ("pair_correlation",))


def _as_data(data):
    if isinstance(data, (str, bytes, _os.PathLike)):
        return load(data)
    return data


def _as_domain(domain, exemplar, scale, name):
    """A Domain from what the user gave for `name` (see synthesize)."""
    if isinstance(domain, Domain):
        return domain
    if domain is None:
        if exemplar is None:
            return None
        if not (isinstance(scale, (int, float)) and scale > 0):
            raise OptionError("scale must be a number > 0, got %r" % (scale,))
        return exemplar.domain.scaled(float(scale))
    if isinstance(domain, str):
        if exemplar is None:
            raise OptionError("%s: a text form needs an exemplar; give a Domain or (lo, hi) corners" % name)
        return Domain.parse(domain, exemplar, float(scale))
    try:
        lo, hi = domain
    except (TypeError, ValueError):
        raise OptionError("%s must be a tessera.Domain, (lo, hi) corners or a --domain text form, got %r"
                          % (name, domain)) from None
    return Domain.box(tuple(lo), tuple(hi))
