//! The library's worker threads: how many ([`thread_count`]), the persistent pools that
//! hold them ([`pool`]), running one job on the caller and the workers at once
//! ([`together`]), and handing a job to the workers while the caller goes on ([`behind`]).
//! Flushing a [`super::Frame`] and setting up the pieces of a long draw
//! ([`super::record_into`]) use them; neither lets the pixels depend on how many there are.

use std::sync::{Arc, Mutex, OnceLock};

/// The worker thread count: `GLES_CM_THREADS` if set to a positive number, otherwise every
/// available core.
pub fn thread_count() -> usize {
    static COUNT: OnceLock<usize> = OnceLock::new();
    *COUNT.get_or_init(|| {
        std::env::var("GLES_CM_THREADS")
            .ok()
            .and_then(|v| v.trim().parse::<usize>().ok())
            .filter(|&n| n > 0)
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
    })
}

/// Runs `work` on the calling thread and on `threads − 1` persistent workers at once, and
/// returns when every copy has returned. The caller starts at once rather than handing the
/// whole job to the pool and sleeping: on a machine where waking a worker takes
/// milliseconds, a late worker then finds the work taken and costs nothing, where before
/// the job could not even begin until one woke. Callers share the work through a queue, so
/// who does which part never changes the result.
pub fn together(threads: usize, work: impl Fn() + Sync) {
    match (threads > 1).then(|| pool(threads - 1)).flatten() {
        Some(p) => p.in_place_scope(|s| {
            for _ in 1..threads {
                s.spawn(|_| work());
            }
            work();
        }),
        None => work(),
    }
}

/// What [`behind`] hands its job: runs a function on `n` (at most the pool's size) of the
/// pool's workers at once, the calling worker among them, and returns when all have.
pub type Spread<'a> = &'a dyn Fn(usize, &(dyn Fn() + Sync));

/// Hands `job` to the pool of `threads` workers and returns at once: the caller goes on
/// while the workers run it, all `threads` of them when `job` spreads its work. Jobs
/// handed over are not ordered among themselves; a caller that needs order waits for one
/// before handing over the next. `Err(job)` when threads cannot be started.
///
/// These are `threads` workers beside the caller, not `threads − 1` as in [`together`]:
/// the caller is busy with other work (recording the next frame) while they run.
pub fn behind<J>(threads: usize, job: J) -> Result<(), J>
where
    J: FnOnce(Spread<'_>) + Send + 'static,
{
    let Some(p) = pool(threads) else {
        return Err(job);
    };
    let own = p.clone();
    p.spawn(move || {
        job(&|n, work| {
            own.in_place_scope(|s| {
                for _ in 1..n.min(threads) {
                    s.spawn(|_| work());
                }
                work();
            })
        })
    });
    Ok(())
}

/// The persistent workers for `threads` threads (built on first use per count and kept, so
/// a flush costs no thread start and workers keep their scratch memory), or `None` when
/// threads cannot be started, and the caller runs alone.
///
/// The pools belong to the process that built them: a child made by `fork()` has none of
/// its parent's threads, so waiting on them would hang it. It builds its own.
pub fn pool(threads: usize) -> Option<Arc<rayon::ThreadPool>> {
    type Pools = Vec<(usize, Arc<rayon::ThreadPool>)>;
    /// The process the pools belong to, its pools, and those inherited from a parent:
    /// kept, never dropped (that would signal threads that are not here), never used.
    static POOLS: Mutex<(u32, Pools, Pools)> = Mutex::new((0, Vec::new(), Vec::new()));
    let mut guard = POOLS.lock().unwrap_or_else(|e| e.into_inner());
    let (owner, pools, inherited) = &mut *guard;
    let me = std::process::id();
    if *owner != me {
        inherited.append(pools);
        *owner = me;
    }
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return Some(p.clone());
    }
    let p = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("gles-cm-{i}"))
        .build()
        .ok()
        .map(Arc::new)?;
    pools.push((threads, p.clone()));
    Some(p)
}
