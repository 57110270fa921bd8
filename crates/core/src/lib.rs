//! The rendering core of `gles-cm` and `m3g`: plain Rust, no FFI types. Both of its users, the
//! GL/EGL state machines of the C library and the M3G scene graph, describe what to draw as a [`RenderState`] plus a
//! [`DrawCall`] and hand it to [`render`], which runs
//! vertex → clip → setup → bin → raster → fragment into a [`Target`].
#![forbid(unsafe_code)]

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

pub mod clip;
pub mod fixed;
pub mod fragment;
pub mod frame;
pub mod lanes;
pub mod multisample;
pub mod pool;
pub mod quality;
pub mod raster;
pub mod reference;
pub mod setup;
pub mod state;
pub mod target;
pub mod texenv;
pub mod texture;
pub mod vertex;

pub use frame::Frame;
pub use state::{CompareFunc, CullFace, RenderState, ShadeModel, Viewport, Winding};
pub use target::{ColorFormat, DepthFormat, Rect, SharedTarget, Target, TargetFormat};
pub use vertex::{AttribArray, AttribSource, ComponentType, DrawCall, Indices, Primitive};

/// Texture units (`GL_MAX_TEXTURE_UNITS`).
pub const TEXTURE_UNITS: usize = 4;

/// The subpixel precision of window coordinates: positions snap to 1/2⁸ pixel.
pub const SUBPIXEL_BITS: u32 = 8;
/// The largest viewport width and height. With [`SUBPIXEL_BITS`] and the guard band
/// ([`clip::GUARD`]) it bounds every snapped coordinate the rasterizer sees below 2²⁴, so
/// edge products stay far below 2⁶³.
pub const MAX_VIEWPORT_DIM: u32 = 8192;

/// The pipeline could not allocate memory for a draw call's vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// Primitives a long draw call is cut into: each piece is transformed, set up and binned
/// while its vertices and primitives are still in cache, and the frame may be flushed
/// between pieces.
const PIECE: usize = 2048;

/// [`record_pieces`] for a multisampled target: the draw once per sample plane the sample
/// coverage mask keeps, moved to the plane's sample position ([`multisample`]). A plane's
/// frame is not flushed during the draw: a flush is for the whole frame, planes and resolve.
fn record_samples(
    state: &RenderState,
    draw: &DrawCall<'_>,
    frame: &mut Frame,
) -> Result<(), OutOfMemory> {
    let mut plane_state = state.clone();
    for (pass, plane) in state
        .multisample
        .passes()
        .into_iter()
        .zip(frame.planes_mut())
    {
        if let Some(pass) = pass {
            plane_state.sample = Some(pass);
            record_pieces(&plane_state, draw, plane, None, pool::thread_count())?;
        }
    }
    Ok(())
}

/// Transforms, clips and sets up `draw` with `state`, recording its primitives in `frame`
/// (for a target of `frame`'s size and format) for a later [`Frame::flush_into`]. The frame
/// grows with the draw: for draws of any size, [`record_into`] bounds it.
pub fn record(
    state: &RenderState,
    draw: &DrawCall<'_>,
    frame: &mut Frame,
) -> Result<(), OutOfMemory> {
    record_pieces(state, draw, frame, None, pool::thread_count())
}

/// Where [`record_into`] sends a frame that fills between pieces of a draw.
pub enum Destination<'a> {
    /// Rasterized at once, on the calling thread and the workers ([`Frame::flush_into`]).
    Now(&'a mut Target),
    /// Rasterized by the workers while the caller records the rest
    /// ([`Frame::flush_behind`]); the caller must not hold the target's lock.
    Behind(Arc<dyn SharedTarget>),
}

/// [`record`] for the frame bound to a target, rasterizing whenever the frame is full
/// between pieces of the draw (into `to`), so a draw of any size rasterizes from a working
/// set that fits in cache. With several threads ([`pool::thread_count`]), consecutive
/// pieces are transformed and set up in parallel and binned in order, so the frame is the
/// same as with one.
pub fn record_into(
    state: &RenderState,
    draw: &DrawCall<'_>,
    frame: &mut Frame,
    to: Destination<'_>,
) -> Result<(), OutOfMemory> {
    record_pieces(state, draw, frame, Some(to), pool::thread_count())
}

/// [`record`] and [`record_into`] with `threads` threads for the set-up of long draws (the
/// library's count, [`pool::thread_count`], but for tests): without a destination the frame is
/// never flushed.
fn record_pieces(
    state: &RenderState,
    draw: &DrawCall<'_>,
    frame: &mut Frame,
    mut to: Option<Destination<'_>>,
    threads: usize,
) -> Result<(), OutOfMemory> {
    let bounds = state.pixel_bounds(frame.bounds());
    if bounds.is_empty() {
        return Ok(());
    }
    if !frame.planes_mut().is_empty() {
        return record_samples(state, draw, frame);
    }
    let fragment = fragment::FragmentKey::new(state, frame.format(), flat_colors(state, draw));
    let mut key = frame.key(fragment.clone());
    // A flush forgets the frame's keys: the piece after it registers this one again.
    let mut make_room = |frame: &mut Frame, key: &mut u32| {
        if frame.is_full() {
            match &mut to {
                Some(Destination::Now(t)) => frame.flush_into(t),
                Some(Destination::Behind(t)) => frame.flush_behind(t.clone()),
                None => {}
            }
            *key = frame.key(fragment.clone());
        }
    };
    let depth = frame.format().depth;
    let threads = threads.min(pieces(draw).len());
    if threads <= 1 {
        return record_serially(
            state,
            pieces(draw),
            frame,
            &mut make_room,
            &mut key,
            bounds,
            depth,
        );
    }
    let pieces: Vec<_> = pieces(draw).collect();
    for batch in pieces.chunks(threads) {
        // While the workers rasterize a frame behind, the cores are theirs: this batch is
        // set up here alone (measured: lit-vbo at 2 threads a third slower with set-up
        // threads crowding them, and as slow with the rasterizing workers taking pieces),
        // straight into the frame.
        if frame.rasterizing() {
            let batch = batch.iter().copied();
            record_serially(state, batch, frame, &mut make_room, &mut key, bounds, depth)?;
            continue;
        }
        // Each piece's primitives land in its own list, binned below in piece order.
        type Slot = Mutex<(frame::PrimList, Option<Result<(), OutOfMemory>>)>;
        let slots: Vec<Slot> = batch
            .iter()
            .map(|_| Mutex::new((frame.spare_list(), None)))
            .collect();
        let next = AtomicUsize::new(0);
        let work = || loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            let Some(piece) = batch.get(k) else { break };
            let mut slot = slots[k].lock().unwrap_or_else(|e| e.into_inner());
            let (list, result) = &mut *slot;
            *result = Some(set_up(state, piece, bounds, depth, list));
        };
        pool::together(threads, work);
        for slot in slots {
            make_room(frame, &mut key);
            let (mut list, result) = slot.into_inner().unwrap_or_else(|e| e.into_inner());
            result.expect("every piece of the batch was set up")?;
            frame.append(&mut list, key);
            frame.keep_list(list);
        }
    }
    Ok(())
}

/// The pieces of a draw one after the other on the calling thread.
#[allow(clippy::too_many_arguments)]
fn record_serially<'a>(
    state: &RenderState,
    pieces: impl Iterator<Item = DrawCall<'a>>,
    frame: &mut Frame,
    make_room: &mut dyn FnMut(&mut Frame, &mut u32),
    key: &mut u32,
    bounds: Rect,
    depth: Option<DepthFormat>,
) -> Result<(), OutOfMemory> {
    for piece in pieces {
        make_room(frame, key);
        let key = *key;
        set_up(state, &piece, bounds, depth, &mut Binned { frame, key })?;
    }
    Ok(())
}

/// Where set-up puts a piece's primitives, in order: a point or a line as it comes, a
/// triangle in the slot it is set up in.
trait Sink: setup::TriangleSlot {
    fn push(&mut self, p: raster::Prim);
    /// Texture-plane storage for the next point or line ([`frame::PrimList::spare_planes`]).
    fn spare_planes(&mut self) -> Option<setup::UnitPlanes>;
}

/// A piece's own list, binned later.
impl Sink for frame::PrimList {
    fn push(&mut self, p: raster::Prim) {
        frame::PrimList::push(self, p);
    }

    fn spare_planes(&mut self) -> Option<setup::UnitPlanes> {
        frame::PrimList::spare_planes(self)
    }
}

/// A frame's list, binned as the primitives come, with fragment state `key`.
struct Binned<'f> {
    frame: &'f mut Frame,
    key: u32,
}

impl setup::TriangleSlot for Binned<'_> {
    fn triangle_slot(&mut self, bbox: Rect) -> &mut setup::Triangle {
        self.frame.triangle_slot(bbox, self.key)
    }
}

impl Sink for Binned<'_> {
    fn push(&mut self, p: raster::Prim) {
        self.frame.prim(p, self.key);
    }

    fn spare_planes(&mut self) -> Option<setup::UnitPlanes> {
        self.frame.spare_planes()
    }
}

/// `draw` cut into pieces of whole primitives. Strips overlap by two vertices and start at
/// an even triangle, so winding and provoking vertices are unchanged; fans and loops stay
/// whole.
fn pieces<'a>(draw: &DrawCall<'a>) -> impl ExactSizeIterator<Item = DrawCall<'a>> + 'a {
    let n = draw.indices.len();
    let (step, overlap) = match draw.primitive {
        Primitive::Points => (PIECE, 0),
        Primitive::Lines => (2 * PIECE, 0),
        Primitive::LineStrip => (PIECE, 1),
        Primitive::Triangles => (3 * PIECE, 0),
        Primitive::TriangleStrip => (PIECE, 2),
        Primitive::LineLoop | Primitive::TriangleFan => (n.max(1), 0),
    };
    // Piece k starts at k·step, and there is a piece k > 0 while k·step + overlap < n
    // (the piece before it stopped short of the end).
    let count = if n <= step + overlap {
        1
    } else {
        (n - overlap).div_ceil(step)
    };
    let draw = *draw;
    (0..count).map(move |k| {
        let start = k * step;
        let mut piece = draw;
        piece.indices = draw.indices.sub(start, (start + step + overlap).min(n));
        piece
    })
}

/// Transforms, clips and sets up one piece, passing its primitives to `emit` in order.
fn set_up(
    state: &RenderState,
    draw: &DrawCall<'_>,
    bounds: Rect,
    depth: Option<DepthFormat>,
    out: &mut impl Sink,
) -> Result<(), OutOfMemory> {
    let mut vertices = VERTICES.take();
    let result = vertex::run_into(state, draw, &mut vertices)
        .map(|()| set_up_vertices(state, draw, &vertices, bounds, depth, out));
    // Storage grown for a very long fan or loop (drawn whole) is not kept.
    if vertices.capacity() <= KEPT_VERTEX_STORAGE {
        VERTICES.set(vertices);
    }
    result
}

/// The most vertex storage (floats and sparse keys) a thread keeps between pieces: a
/// piece of [`PIECE`] triangles with every attribute takes under a quarter of it.
const KEPT_VERTEX_STORAGE: usize = 1 << 20;

thread_local! {
    /// Each thread's vertex storage, reused from piece to piece (so from draw to draw):
    /// three allocations and frees per draw were 7 % of the work outside rasterization in
    /// a scene of many small draws (draws-10k).
    static VERTICES: std::cell::Cell<vertex::Vertices> = std::cell::Cell::default();
}

/// Whether each primitive of `draw` takes one color, set up and shaded without color planes:
/// under flat shading the provoking vertex's, and when every vertex has the same color (no
/// lighting, no color array) that color, which interpolation would give back only up to
/// rounding. A draw of one color is common (text, sprites, untextured UI, wireframes).
pub fn flat_colors(state: &RenderState, draw: &DrawCall<'_>) -> bool {
    state.shade_model == ShadeModel::Flat
        || (state.lighting.is_none() && matches!(draw.color, AttribSource::Constant(_)))
}

/// [`set_up`] of the piece's primitives from its transformed `vertices`.
fn set_up_vertices(
    state: &RenderState,
    draw: &DrawCall<'_>,
    vertices: &vertex::Vertices,
    bounds: Rect,
    depth: Option<DepthFormat>,
    out: &mut impl Sink,
) {
    let prim = draw.primitive;
    let flat = flat_colors(state, draw);
    if prim == Primitive::Points {
        for k in 0..draw.indices.len() {
            let v = vertices.get(draw.indices.get(k));
            if clip::point(v) {
                if let Some(p) = raster::point::setup(state, v, bounds, out.spare_planes()) {
                    out.push(raster::Prim::Point(p));
                }
            }
        }
    } else if prim.is_line() {
        prim.for_each_line(&draw.indices, |a, b| {
            let (va, vb) = (vertices.get(a), vertices.get(b));
            clip::line(va, vb, |ca, cb| {
                let spare = out.spare_planes();
                if let Some(l) =
                    raster::line::setup(state, ca, cb, flat.then_some(vb), bounds, spare)
                {
                    out.push(raster::Prim::Line(l));
                }
            });
        });
    } else {
        // Triangles are clipped to the guard band only: their pixels stop at the viewport.
        let vp = state.viewport;
        let bounds = bounds.intersect(Rect::new(vp.x, vp.y, vp.width, vp.height));
        vertices.for_each_kept_triangle(prim, &draw.indices, |slots| {
            set_up_triangle(state, vertices, slots, flat, bounds, depth, out);
        });
    }
}

/// Clips (when a vertex may need it) and sets up the triangle of the vertices in `slots`,
/// which `rejects` kept, with its last vertex's color when `flat`. Out of line, so the
/// triangle loop, where most triangles of a scene outside the view end, does not pay for
/// this function's stack frame.
#[inline(never)]
fn set_up_triangle(
    state: &RenderState,
    vertices: &vertex::Vertices,
    slots: [usize; 3],
    flat: bool,
    bounds: Rect,
    depth: Option<DepthFormat>,
    out: &mut impl Sink,
) {
    let (a, b, c) = (
        vertices.at(slots[0]),
        vertices.at(slots[1]),
        vertices.at(slots[2]),
    );
    // Inside the clip volume (most triangles), the clipper would pass it on as it is.
    if !vertices.may_clip(slots[0], slots[1], slots[2]) {
        let corners = vertices.corners(slots);
        setup::triangle(
            state,
            [a, b, c],
            corners,
            flat.then_some(c),
            bounds,
            depth,
            out,
        );
        return;
    }
    // A clipped polygon is convex: fan it out from its first vertex.
    clip::triangle(a, b, c, |poly: &[vertex::VertexRef<'_>]| {
        for i in 1..poly.len() - 1 {
            let tri = [poly[0], poly[i], poly[i + 1]];
            setup::triangle(state, tri, None, flat.then_some(c), bounds, depth, out);
        }
    });
}

/// Draws `draw` with `state` into `target` and returns when every pixel is written.
pub fn render(
    state: &RenderState,
    draw: &DrawCall<'_>,
    target: &mut Target,
) -> Result<(), OutOfMemory> {
    let mut frame = Frame::for_target(target);
    record(state, draw, &mut frame)?;
    frame.flush_into(target);
    Ok(())
}

#[cfg(test)]
mod tests;
