//! Binning: the [`Frame`], deferred, banded, parallel rasterization (ARCHITECTURE
//! decision 5). The threads it runs on are [`super::pool`]'s.
//!
//! A draw call is transformed, clipped and set up at once (the application may change its
//! arrays right after), and each resulting primitive is recorded in the command list of every
//! band of [`BAND_ROWS`] rows it touches. At a flush point the bands are rasterized by worker
//! threads; one thread owns a band and replays its commands in submission order, so the
//! pixels never depend on the thread count. Bands are whole rows, so each is one contiguous
//! slice of every buffer and needs no locking.
//!
//! A frame that fills in the middle of the work can be rasterized *behind* the caller
//! ([`Frame::flush_behind`]): the workers replay it into a [`SharedTarget`] while the caller
//! transforms, sets up and bins the next primitives into the same (now empty) frame. Only
//! one batch is behind at a time, and every flush waits for it first, so batches land in
//! the order they were recorded.

use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};

use super::fragment::FragmentKey;
use super::pool::{self, thread_count, together, Spread};
use super::raster::Prim;
use super::setup::{Triangle, TriangleSlot, UnitPlanes};
use super::target::{BandMut, Rect, SharedTarget, Target, TargetFormat};

/// Rows per band: small enough that several bands per thread balance the load, large
/// enough that a triangle's setup is shared by many rows.
pub const BAND_ROWS: u32 = 16;

/// Band commands below which a flush runs on the calling thread alone.
const SMALL_WORK: usize = 64;

/// Pending primitives beyond which a frame flushes by itself, bounding its memory.
const MAX_PENDING: usize = 1 << 12;

#[derive(Clone, Copy, Debug)]
enum Command {
    Prim(u32),
    ClearColor { rect: Rect, word: u32, keep: u32 },
    ClearDepth { rect: Rect, value: u32 },
    ClearStencil { rect: Rect, value: u8, mask: u8 },
}

/// Work recorded for one target and not yet rasterized.
pub struct Frame {
    format: TargetFormat,
    width: u32,
    height: u32,
    prims: PrimList,
    /// The fragment key of each primitive, apart so that a primitive moves into `prims`
    /// straight from where it was built instead of through a tuple.
    prim_keys: Vec<u32>,
    keys: Vec<FragmentKey>,
    bands: Vec<Vec<Command>>,
    pending: usize,
    /// For a multisampled target, one frame per sample plane ([`super::multisample`]):
    /// primitives are recorded there, and this frame only forwards.
    planes: Vec<Frame>,
    /// The batch the workers are rasterizing ([`Frame::flush_behind`]).
    behind: Option<Arc<Behind>>,
    /// The frame of the last finished batch, emptied, to record into after the next
    /// handover (its lists keep their capacity).
    spare: Option<Box<Frame>>,
    /// Lists of primitives set up apart, kept for [`Frame::spare_list`].
    lists: Vec<PrimList>,
}

/// Primitives in order, in storage kept from use to use: the first `live` are the list's,
/// the rest old ones, which a triangle is set up over ([`TriangleSlot`]) rather than over a
/// blank written first. The frame's own list, and a piece's set up on a helper thread for
/// [`Frame::append`].
#[derive(Default)]
pub struct PrimList {
    prims: Vec<Prim>,
    live: usize,
}

impl PrimList {
    /// Stores `p` as the next primitive.
    pub fn push(&mut self, p: Prim) {
        match self.prims.get_mut(self.live) {
            Some(old) => *old = p,
            None => self.prims.push(p),
        }
        self.live += 1;
    }

    pub fn as_slice(&self) -> &[Prim] {
        &self.prims[..self.live]
    }

    /// The texture-plane storage of the old primitive the next one replaces, if it has
    /// any: a textured point or line set up with it allocates nothing.
    pub fn spare_planes(&mut self) -> Option<UnitPlanes> {
        self.prims.get_mut(self.live).and_then(Prim::take_planes)
    }
}

/// The list's next primitive, a triangle set up in place.
impl TriangleSlot for PrimList {
    fn triangle_slot(&mut self, _: Rect) -> &mut Triangle {
        if self.live == self.prims.len() {
            self.prims.push(Prim::Triangle(Triangle::BLANK));
        }
        self.live += 1;
        self.prims[self.live - 1].reuse_as_triangle()
    }
}

/// A batch handed to the workers: its frame comes back here, emptied, when it has been
/// rasterized (or the panic that stopped it).
#[derive(Default)]
struct Behind {
    done: Mutex<Option<std::thread::Result<Box<Frame>>>>,
    ready: Condvar,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Frame {
    /// An empty frame for targets of this size and format.
    pub fn new(width: u32, height: u32, format: TargetFormat) -> Frame {
        Frame {
            format,
            width,
            height,
            prims: PrimList::default(),
            prim_keys: Vec::new(),
            keys: Vec::new(),
            bands: vec![Vec::new(); height.div_ceil(BAND_ROWS) as usize],
            pending: 0,
            planes: Vec::new(),
            behind: None,
            spare: None,
            lists: Vec::new(),
        }
    }

    /// An empty frame for `target`, with a frame per sample plane when it is multisampled.
    pub fn for_target(target: &Target) -> Frame {
        let (w, h, f) = (target.width(), target.height(), target.format());
        let mut frame = Frame::new(w, h, f);
        frame.planes = (0..target.samples()).map(|_| Frame::new(w, h, f)).collect();
        frame
    }

    /// The per-sample frames: empty unless the frame is for a multisampled target.
    pub fn planes_mut(&mut self) -> &mut [Frame] {
        &mut self.planes
    }

    /// True when `target` is the kind of target this frame records for.
    pub fn fits(&self, target: &Target) -> bool {
        (self.width, self.height, self.format) == (target.width(), target.height(), target.format())
            && self.planes.len() == target.samples() as usize
    }

    pub fn format(&self) -> TargetFormat {
        self.format
    }

    pub fn bounds(&self) -> Rect {
        Rect::new(0, 0, self.width as i32, self.height as i32)
    }

    pub fn is_empty(&self) -> bool {
        self.pending == 0 && self.planes.iter().all(Frame::is_empty)
    }

    /// True when the frame holds enough work that it should be flushed before more is added.
    pub fn is_full(&self) -> bool {
        self.prims.live >= MAX_PENDING || self.planes.iter().any(Frame::is_full)
    }

    /// [`PrimList::spare_planes`] of the frame's list.
    pub fn spare_planes(&mut self) -> Option<UnitPlanes> {
        self.prims.spare_planes()
    }

    /// Registers the fragment state for the primitives that follow, returning its number.
    pub fn key(&mut self, key: FragmentKey) -> u32 {
        if self.keys.last() != Some(&key) {
            self.keys.push(key);
        }
        (self.keys.len() - 1) as u32
    }

    fn band_range(&self, y0: i32, y1: i32) -> std::ops::Range<usize> {
        let b0 = (y0.max(0) as u32 / BAND_ROWS) as usize;
        let b1 = ((y1.max(0) as u32).div_ceil(BAND_ROWS) as usize).min(self.bands.len());
        b0..b1
    }

    fn record(&mut self, y0: i32, y1: i32, c: Command) {
        for b in self.band_range(y0, y1) {
            self.bands[b].push(c);
        }
        self.pending += 1;
    }

    /// Records `p` with fragment state `key`.
    #[inline]
    pub fn prim(&mut self, p: Prim, key: u32) {
        self.bin(p.bbox(), key);
        self.prims.push(p);
    }

    /// [`Frame::prim`] for each primitive of `list` in order, which is left empty. The
    /// primitives are exchanged with old ones of the frame's storage rather than moved, so
    /// that neither storage is allocated or dropped from batch to batch.
    pub fn append(&mut self, list: &mut PrimList, key: u32) {
        let at = self.prims.live;
        for (k, p) in list.as_slice().iter().enumerate() {
            let b = p.bbox();
            self.record(b.y0, b.y1, Command::Prim((at + k) as u32));
        }
        let n = list.live;
        let old = &mut self.prims.prims[at..];
        let swapped = old.len().min(n);
        old[..swapped].swap_with_slice(&mut list.prims[..swapped]);
        self.prims.prims.extend(list.prims.drain(swapped..n));
        self.prims.live += n;
        list.live = 0;
        self.prim_keys.resize(self.prims.live, key);
    }

    /// An empty list for [`Frame::append`], with the storage of one appended before.
    pub fn spare_list(&mut self) -> PrimList {
        self.lists.pop().unwrap_or_default()
    }

    /// Keeps `list`'s storage for [`Frame::spare_list`].
    pub fn keep_list(&mut self, list: PrimList) {
        self.lists.push(list);
    }

    /// [`Frame::prim`] for a triangle that covers `bbox`, binned now and then set up in
    /// the storage returned (`setup::TriangleSlot`): an old primitive's where there is one.
    #[inline]
    pub fn triangle_slot(&mut self, bbox: Rect, key: u32) -> &mut Triangle {
        self.bin(bbox, key);
        self.prims.triangle_slot(bbox)
    }

    /// Bins the next primitive, which covers `bbox`.
    #[inline]
    fn bin(&mut self, bbox: Rect, key: u32) {
        let i = self.prims.live;
        self.record(bbox.y0, bbox.y1, Command::Prim(i as u32));
        self.prim_keys.push(key);
    }

    pub fn clear_color(&mut self, rect: Rect, word: u32, keep: u32) {
        if !self.planes.is_empty() {
            for p in &mut self.planes {
                p.clear_color(rect, word, keep);
            }
            return;
        }
        self.record(rect.y0, rect.y1, Command::ClearColor { rect, word, keep });
    }

    pub fn clear_depth(&mut self, rect: Rect, value: u32) {
        if !self.planes.is_empty() {
            for p in &mut self.planes {
                p.clear_depth(rect, value);
            }
            return;
        }
        self.record(rect.y0, rect.y1, Command::ClearDepth { rect, value });
    }

    pub fn clear_stencil(&mut self, rect: Rect, value: u8, mask: u8) {
        if !self.planes.is_empty() {
            for p in &mut self.planes {
                p.clear_stencil(rect, value, mask);
            }
            return;
        }
        self.record(
            rect.y0,
            rect.y1,
            Command::ClearStencil { rect, value, mask },
        );
    }

    /// Rasterizes everything recorded into `target` on the library's threads
    /// ([`thread_count`]), then empties the frame. `target` must be the kind the frame
    /// records for ([`Frame::fits`]).
    pub fn flush_into(&mut self, target: &mut Target) {
        self.flush(target, thread_count());
    }

    /// [`Frame::flush_into`] when the frame is full, so the work that follows starts from
    /// an empty frame and what is pending stays bounded.
    pub fn flush_if_full(&mut self, target: &mut Target) {
        if self.is_full() {
            self.flush_into(target);
        }
    }

    /// [`Frame::flush_into`] on exactly `threads` threads: what the tests of thread-count
    /// invariance and the benchmarks at a given count need.
    pub fn flush(&mut self, target: &mut Target, threads: usize) {
        self.wait();
        if self.is_empty() {
            return;
        }
        debug_assert!(self.fits(target));
        if !self.planes.is_empty() {
            // Plane by plane, each on all threads, then the resolve: the same pixels for
            // any thread count.
            for (frame, plane) in self.planes.iter_mut().zip(target.sample_planes_mut()) {
                frame.flush(plane, threads);
            }
            target.resolve();
            return;
        }
        self.rasterize(target, threads, &|n, work| together(n, work));
        self.clear();
    }

    /// Hands what is recorded to the workers, which rasterize it into `target` while the
    /// caller records more into this frame (emptied at once), on the library's threads
    /// ([`thread_count`]). With one thread, or for a multisampled target, it is
    /// [`Frame::flush_into`].
    ///
    /// The batch handed over before is waited for first, and so it is by every flush and
    /// by [`Frame::wait`]: the caller must not hold `target`'s lock when it calls them.
    pub fn flush_behind(&mut self, target: Arc<dyn SharedTarget>) {
        self.flush_behind_on(target, thread_count());
    }

    /// [`Frame::flush_behind`] on exactly `threads` worker threads.
    pub fn flush_behind_on(&mut self, target: Arc<dyn SharedTarget>, threads: usize) {
        self.wait();
        if self.is_empty() {
            return;
        }
        if threads <= 1 || !self.planes.is_empty() {
            return self.flush(&mut lock(target.target()), threads);
        }
        let empty = match self.spare.take() {
            Some(frame) => *frame,
            None => Frame::new(self.width, self.height, self.format),
        };
        let mut full = std::mem::replace(self, empty);
        self.lists = std::mem::take(&mut full.lists);
        let behind = Arc::new(Behind::default());
        let signal = behind.clone();
        let job = move |spread: Spread<'_>| {
            let result = catch_unwind(AssertUnwindSafe(|| {
                full.rasterize(&mut lock(target.target()), threads, spread);
                full.clear();
                Box::new(full)
            }));
            *lock(&signal.done) = Some(result);
            signal.ready.notify_all();
        };
        if let Err(job) = pool::behind(threads, job) {
            job(&|_, work| work());
        }
        self.behind = Some(behind);
    }

    /// True while a batch handed to the workers ([`Frame::flush_behind`]) is still being
    /// rasterized.
    pub fn rasterizing(&self) -> bool {
        self.behind
            .as_ref()
            .is_some_and(|b| lock(&b.done).is_none())
    }

    /// Returns when the batch handed to the workers ([`Frame::flush_behind`]) is in its
    /// target. A panic that stopped it is raised again here, on the caller's thread.
    pub fn wait(&mut self) {
        if let Some(behind) = self.behind.take() {
            match behind.finished() {
                Ok(frame) => self.spare = Some(frame),
                Err(panic) => resume_unwind(panic),
            }
        }
    }

    /// Replays every band with commands into `target` on up to `threads` threads, which
    /// `spread` runs; each band is replayed whole by whichever thread takes it, so the
    /// pixels do not depend on the scheduling.
    fn rasterize(&self, target: &mut Target, threads: usize, spread: Spread<'_>) {
        let mut bands: Vec<(BandMut<'_>, &[Command])> = target
            .bands_mut(BAND_ROWS)
            .into_iter()
            .zip(self.bands.iter().map(Vec::as_slice))
            .filter(|(_, cmds)| !cmds.is_empty())
            .collect();
        // Starting a thread costs tens of microseconds: below a few primitives per band it
        // is not worth it (the result is the same either way).
        let work: usize = bands.iter().map(|(_, cmds)| cmds.len()).sum();
        let threads = if work < SMALL_WORK {
            1
        } else {
            threads.clamp(1, bands.len().max(1))
        };
        let queue = Mutex::new(bands.iter_mut());
        spread(threads, &|| loop {
            let next = lock(&queue).next();
            let Some((band, cmds)) = next else { break };
            self.replay(band, cmds);
        });
    }

    /// Forgets what was recorded, keeping the lists' capacity.
    fn clear(&mut self) {
        self.prims.live = 0;
        self.prim_keys.clear();
        self.keys.clear();
        self.bands.iter_mut().for_each(Vec::clear);
        self.pending = 0;
    }

    fn replay(&self, band: &mut BandMut<'_>, cmds: &[Command]) {
        let rows = band.y0..band.y0 + band.rows;
        for c in cmds {
            match *c {
                Command::Prim(i) => {
                    let p = &self.prims.prims[i as usize];
                    let key = &self.keys[self.prim_keys[i as usize] as usize];
                    key.shade(p, rows.clone(), band);
                }
                Command::ClearColor { rect, word, keep } => band.clear_color(rect, word, keep),
                Command::ClearDepth { rect, value } => band.clear_depth(rect, value),
                Command::ClearStencil { rect, value, mask } => {
                    band.clear_stencil(rect, value, mask)
                }
            }
        }
    }
}

impl Behind {
    /// Blocks until the workers are done with the batch.
    fn finished(&self) -> std::thread::Result<Box<Frame>> {
        let mut done = lock(&self.done);
        loop {
            match done.take() {
                Some(result) => return result,
                None => done = self.ready.wait(done).unwrap_or_else(|e| e.into_inner()),
            }
        }
    }
}

impl Drop for Frame {
    /// A batch still behind finishes before the frame goes, so its target holds everything
    /// that was handed over. A panic that stopped it is not raised again here (that could
    /// abort while unwinding); the worker's panic message has reported it.
    fn drop(&mut self) {
        if let Some(behind) = self.behind.take() {
            let _ = behind.finished();
        }
    }
}
