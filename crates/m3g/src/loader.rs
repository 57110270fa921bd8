//! The M3G `Loader`: the .m3g file format (specification chapter "File Format for Mobile 3D
//! Graphics API") and PNG images.
//!
//! [`Loader::load`] takes the bytes of a .m3g or PNG file and returns its root objects (every
//! object no other loaded object refers to, in file order). [`Loader::load_path`] reads a file
//! and resolves relative external references against its folder; a [`Loader`] value made with
//! [`Loader::new`] can carry a base folder and a resolver callback for other URIs.
//!
//! Everything the specification calls an error is one: a bad identifier, section length,
//! compression scheme, Adler-32 checksum, total file size, object type, Boolean, enumeration,
//! Float32 (only normal numbers and +0.0 are accepted), a forward, self, header or wrong-class
//! reference, leftover object bytes, and every value the corresponding API call would reject.
//! The [`LoadError`] (Java's `IOException`) names the object index, its class and the field.
//! No allocation is made that the input does not justify: every count is checked against the
//! bytes left before anything is allocated, zlib output is bounded by the declared length and
//! by deflate's maximum ratio, mutable images (which carry no pixels) are capped at
//! [`MAX_MUTABLE_IMAGE_PIXELS`], and everything a load allocates is counted against its
//! memory budget before it is allocated (see [Loader's limits](Loader#limits)).

mod objects;
mod png;
mod render;

use std::collections::HashSet;
use std::fmt;
use std::path::{Path, PathBuf};

pub use render::{render_roots, RenderTarget};

use super::{Object3D, Result};

/// The 12-byte M3G file identifier.
pub const FILE_IDENTIFIER: [u8; 12] = [
    0xAB, 0x4A, 0x53, 0x52, 0x31, 0x38, 0x34, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A,
];
/// The PNG signature.
pub const PNG_SIGNATURE: [u8; 8] = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];
/// The largest mutable Image2D (width × height) a file may declare: such an image has no pixel
/// data in the file, so its size is not bounded by the input (an implementation limit).
pub const MAX_MUTABLE_IMAGE_PIXELS: u64 = 4096 * 4096;
/// The deepest nesting of external references followed.
pub const MAX_REFERENCE_DEPTH: usize = 16;

/// The user parameters of a loaded object (parameter ID → bytes), stored as its user object
/// (`Object3D::user_object`), as the Java Loader stores a `Hashtable`. Objects without
/// parameters keep a `None` user object.
pub type UserParameters = std::collections::BTreeMap<i32, Vec<u8>>;

/// A resolver for external-reference URIs that are not relative file names: gets the URI,
/// returns the referenced file's bytes.
pub type Resolver = dyn Fn(&str) -> std::io::Result<Vec<u8>>;

/// The details of a load failure (Java's `IOException`, [`Error::Io`](crate::Error::Io)):
/// where it happened and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadError {
    /// The object index (1 = the header) when the error is inside an object.
    pub object: Option<u32>,
    /// The class of that object.
    pub class: Option<&'static str>,
    /// The field, when one is to blame.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl LoadError {
    pub(crate) fn file(message: impl Into<String>) -> LoadError {
        LoadError {
            object: None,
            class: None,
            field: None,
            message: message.into(),
        }
    }

    /// The Java exception's name: always `"IOException"`.
    pub fn java_name(&self) -> &'static str {
        "IOException"
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(i) = self.object {
            write!(f, "object {i}")?;
            if let Some(c) = self.class {
                write!(f, " ({c})")?;
            }
            if let Some(fl) = &self.field {
                write!(f, ", field {fl}")?;
            }
            write!(f, ": ")?;
        } else if let Some(fl) = &self.field {
            write!(f, "{fl}: ")?;
        }
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for LoadError {}

/// The result of a load step.
pub(crate) type LoadResult<T> = std::result::Result<T, LoadError>;

/// The header object of a .m3g file.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Header {
    /// VersionNumber (always {1, 0}).
    pub version: [u8; 2],
    /// hasExternalReferences.
    pub has_external_references: bool,
    /// TotalFileSize.
    pub total_file_size: u32,
    /// ApproximateContentSize.
    pub approximate_content_size: u32,
    /// AuthoringField.
    pub authoring_field: String,
}

/// Everything one load produced.
#[derive(Clone, Debug, Default)]
pub struct Loaded {
    /// The root objects (not referenced by any other loaded object), in index order.
    pub roots: Vec<Object3D>,
    /// Every object in index order from index 2 (index `i` is `objects[i - 2]`); an external
    /// reference's slot holds the object it resolved to.
    pub objects: Vec<Object3D>,
    /// The header (default for a PNG).
    pub header: Header,
}

/// The default memory budget of one load: 256 MiB. Far above any content the corpus holds
/// (its largest file needs a few MiB) and above one 4096² RGBA texture (64 MiB) with room
/// to spare, yet small enough that a hostile file cannot exhaust a phone-sized or
/// CI-sized machine.
pub const DEFAULT_MAX_MEMORY: u64 = 256 << 20;

/// The file access of a [`Loader`]: the real file system ([`StdFileSystem`]) unless
/// [`Loader::with_file_system`] supplies another (an in-memory one for tests and fuzzing,
/// [`MemoryFileSystem`]).
pub trait FileSystem {
    /// The canonical form of `path` (absolute, no `.` or `..`, symbolic links resolved);
    /// an error when it does not exist.
    fn canonicalize(&self, path: &Path) -> std::io::Result<PathBuf>;
    /// The bytes of the regular file at `path`. An error, without blocking, when it is not
    /// a regular file (a FIFO, a device, a folder), and an error as soon as it turns out
    /// longer than `limit` bytes (without reading more than `limit + 1`).
    fn read_regular(&self, path: &Path, limit: u64) -> std::io::Result<Vec<u8>>;
}

/// The operating system's file system.
#[derive(Clone, Copy, Debug, Default)]
pub struct StdFileSystem;

impl FileSystem for StdFileSystem {
    fn canonicalize(&self, path: &Path) -> std::io::Result<PathBuf> {
        std::fs::canonicalize(path)
    }

    fn read_regular(&self, path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
        use std::io::Read;
        let not_regular = || {
            std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                "not a regular file (only regular files are read)",
            )
        };
        if !std::fs::metadata(path)?.is_file() {
            return Err(not_regular());
        }
        // The path may have been replaced by a FIFO since the check: a non-blocking open
        // returns at once instead of waiting for a writer, and the check is repeated on
        // what was actually opened.
        let mut opts = std::fs::OpenOptions::new();
        opts.read(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::custom_flags(&mut opts, libc::O_NONBLOCK);
        let f = opts.open(path)?;
        let meta = f.metadata()?;
        if !meta.is_file() {
            return Err(not_regular());
        }
        if meta.len() > limit {
            return Err(too_long(limit));
        }
        let mut out = Vec::new();
        // A file that grows while read is still cut at the limit.
        f.take(limit + 1).read_to_end(&mut out)?;
        if out.len() as u64 > limit {
            return Err(too_long(limit));
        }
        Ok(out)
    }
}

fn too_long(limit: u64) -> std::io::Error {
    std::io::Error::other(format!(
        "longer than the {limit} bytes left in the load's memory budget"
    ))
}

/// An in-memory file system: regular files by absolute path, every folder implied by
/// them. For tests and fuzzing of external references without touching the disk.
#[derive(Clone, Debug, Default)]
pub struct MemoryFileSystem {
    /// The files, by normalized absolute path.
    pub files: std::collections::HashMap<PathBuf, Vec<u8>>,
}

impl MemoryFileSystem {
    /// An empty file system.
    pub fn new() -> MemoryFileSystem {
        MemoryFileSystem::default()
    }

    /// Adds (or replaces) the file at `path` (made absolute from `/`).
    pub fn insert(&mut self, path: impl AsRef<Path>, bytes: Vec<u8>) {
        self.files.insert(normalize(path.as_ref()), bytes);
    }
}

/// `path` made absolute from `/`, with `.` and `..` resolved lexically.
fn normalize(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out = PathBuf::from("/");
    for c in path.components() {
        match c {
            Component::ParentDir => {
                out.pop();
            }
            Component::Normal(n) => out.push(n),
            _ => {}
        }
    }
    out
}

impl FileSystem for MemoryFileSystem {
    fn canonicalize(&self, path: &Path) -> std::io::Result<PathBuf> {
        let p = normalize(path);
        let is_dir = || self.files.keys().any(|f| f.starts_with(&p) && *f != p);
        if self.files.contains_key(&p) || is_dir() {
            Ok(p)
        } else {
            Err(std::io::ErrorKind::NotFound.into())
        }
    }

    fn read_regular(&self, path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
        match self.files.get(&normalize(path)) {
            Some(b) if b.len() as u64 > limit => Err(too_long(limit)),
            Some(b) => Ok(b.clone()),
            None => Err(std::io::ErrorKind::NotFound.into()),
        }
    }
}

/// The M3G Loader.
///
/// | Java | Rust |
/// |---|---|
/// | `Loader.load(byte[], int)` | [`Loader::load`] (slice the offset off) |
/// | `Loader.load(String)` | [`Loader::load_path`] (a file name) or [`Loader::load_bytes`] with a [resolver](Loader::with_resolver) |
///
/// # Limits
///
/// One load (a call of `load_file` or `load_bytes`, with every external reference it
/// follows) has a memory budget, [`DEFAULT_MAX_MEMORY`] unless
/// [`with_max_memory`](Self::with_max_memory) sets another. What the load would allocate is
/// counted before it is allocated: each file read, each inflated zlib section, each
/// Image2D's pixels (a PNG's from its header, before decoding), each triangle strip's
/// expanded triangles, and each object's own size. Past the budget the load stops with a
/// [`LoadError`] whose message says "memory budget".
///
/// External references: each distinct file (by canonical path) or resolver URI is loaded
/// once per load, every reference to it getting the same object; a file referring back
/// to one being loaded is an error ("loop"), as is nesting deeper than
/// [`MAX_REFERENCE_DEPTH`]. Only regular files are read (a FIFO, device or folder is an
/// error, found without blocking), and only inside the folder of the referencing file
/// (or its subfolders): `../x.m3g`, an absolute `file://` URI elsewhere, or a symbolic
/// link leading out is refused unless [`allow_outside_references`](
/// Self::allow_outside_references) is set.
pub struct Loader {
    base: Option<PathBuf>,
    resolver: Option<Box<Resolver>>,
    fs: Box<dyn FileSystem>,
    max_memory: u64,
    allow_outside: bool,
    /// Files being loaded (loop detection).
    active: Vec<String>,
    /// Bytes counted against the budget in this load.
    used: u64,
    /// The first root of every file or URI loaded in this load, by canonical key.
    cache: std::collections::HashMap<String, Object3D>,
}

impl Default for Loader {
    fn default() -> Self {
        Loader {
            base: None,
            resolver: None,
            fs: Box::new(StdFileSystem),
            max_memory: DEFAULT_MAX_MEMORY,
            allow_outside: false,
            active: Vec::new(),
            used: 0,
            cache: Default::default(),
        }
    }
}

impl fmt::Debug for Loader {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Loader")
            .field("base", &self.base)
            .field("resolver", &self.resolver.is_some())
            .field("max_memory", &self.max_memory)
            .field("allow_outside", &self.allow_outside)
            .finish()
    }
}

impl Loader {
    /// A loader with no base folder, no resolver, the real file system and the default
    /// memory budget.
    pub fn new() -> Loader {
        Loader::default()
    }

    /// Resolves relative external references against `dir`.
    pub fn with_base_dir(mut self, dir: impl Into<PathBuf>) -> Loader {
        self.base = Some(dir.into());
        self
    }

    /// Resolves URIs that are not relative file names (or any URI when there is no base
    /// folder) through `f`. What `f` returns is counted against the budget after the call:
    /// bounding its own reads is up to `f`.
    pub fn with_resolver(
        mut self,
        f: impl Fn(&str) -> std::io::Result<Vec<u8>> + 'static,
    ) -> Loader {
        self.resolver = Some(Box::new(f));
        self
    }

    /// Reads files through `fs` instead of the operating system.
    pub fn with_file_system(mut self, fs: impl FileSystem + 'static) -> Loader {
        self.fs = Box::new(fs);
        self
    }

    /// Sets the memory budget of each load, in bytes (see [Limits](Self#limits)).
    pub fn with_max_memory(mut self, bytes: u64) -> Loader {
        self.max_memory = bytes;
        self
    }

    /// Lets external references name files outside the referencing file's folder.
    pub fn allow_outside_references(mut self, allow: bool) -> Loader {
        self.allow_outside = allow;
        self
    }

    /// `Loader.load(byte[], 0)`: the root objects of a .m3g or PNG file in memory. External
    /// references cannot be resolved (use a [`Loader`] with a resolver).
    ///
    /// ```
    /// use m3g::prelude::*;
    ///
    /// # fn main() -> m3g::Result<()> {
    /// let group = Group::new();
    /// group.set_user_id(42);
    /// let bytes = m3g::writer::save(&[group.as_object3d()], false)?;
    /// let roots = Loader::load(&bytes)?;
    /// let loaded = roots[0].downcast::<Group>().expect("a Group");
    /// assert_eq!(loaded.user_id(), 42);
    /// // A broken file is an IOException naming what is wrong.
    /// let err = Loader::load(&bytes[..20]).unwrap_err();
    /// assert!(matches!(err, Error::Io(_)), "{err}");
    /// # Ok(())
    /// # }
    /// ```
    pub fn load(bytes: &[u8]) -> Result<Vec<Object3D>> {
        Ok(Loader::new().load_bytes(bytes)?.roots)
    }

    /// The root objects of the .m3g or PNG file at `path`; relative external references are
    /// resolved against its folder.
    pub fn load_path(path: impl AsRef<Path>) -> Result<Vec<Object3D>> {
        Ok(Loader::new().load_file(path)?.roots)
    }

    /// Loads a file (its folder becomes the base for relative references).
    pub fn load_file(&mut self, path: impl AsRef<Path>) -> Result<Loaded> {
        self.begin();
        let path = path.as_ref();
        let key = self
            .fs
            .canonicalize(path)
            .map_err(|e| LoadError::file(format!("cannot read {}: {e}", path.display())))?;
        let bytes = self.read(&key)?;
        let saved = self.base.take();
        self.base = Some(
            key.parent()
                .map(Path::to_path_buf)
                .unwrap_or_else(|| PathBuf::from("/")),
        );
        let r = self.load_keyed(&bytes, key.display().to_string());
        self.base = saved;
        self.end();
        Ok(r?)
    }

    /// Loads bytes with this loader's base folder and resolver.
    pub fn load_bytes(&mut self, bytes: &[u8]) -> Result<Loaded> {
        self.begin();
        let r = self.load_inner(bytes);
        self.end();
        Ok(r?)
    }

    fn begin(&mut self) {
        self.used = 0;
        self.active.clear();
        self.cache.clear();
    }

    fn end(&mut self) {
        // The objects belong to the caller now; the loader keeps nothing alive.
        self.cache.clear();
    }

    /// Counts `bytes` more against the load's memory budget, before they are allocated.
    pub(crate) fn charge(&mut self, bytes: u64, what: impl FnOnce() -> String) -> LoadResult<()> {
        let total = self.used.saturating_add(bytes);
        if total > self.max_memory {
            return Err(LoadError::file(format!(
                "{} needs {bytes} bytes, over the load's memory budget of {} bytes ({} already used; Loader::with_max_memory sets it)",
                what(),
                self.max_memory,
                self.used
            )));
        }
        self.used = total;
        Ok(())
    }

    /// What is left of the budget.
    pub(crate) fn remaining(&self) -> u64 {
        self.max_memory.saturating_sub(self.used)
    }

    /// Reads the regular file at `path` (canonical), counted against the budget.
    fn read(&mut self, path: &Path) -> LoadResult<Vec<u8>> {
        let bytes = self
            .fs
            .read_regular(path, self.remaining())
            .map_err(|e| LoadError::file(format!("cannot read {}: {e}", path.display())))?;
        self.charge(bytes.len() as u64, || format!("reading {}", path.display()))?;
        Ok(bytes)
    }

    fn load_keyed(&mut self, bytes: &[u8], key: String) -> LoadResult<Loaded> {
        if self.active.contains(&key) {
            return Err(LoadError::file(format!(
                "external reference loop through {key}"
            )));
        }
        if self.active.len() >= MAX_REFERENCE_DEPTH {
            return Err(LoadError::file("external references nested too deeply"));
        }
        self.active.push(key);
        let r = self.load_inner(bytes);
        self.active.pop();
        r
    }

    fn load_inner(&mut self, bytes: &[u8]) -> LoadResult<Loaded> {
        if bytes.starts_with(&PNG_SIGNATURE) {
            let img = png::decode(self, bytes)?;
            let o: Object3D = img.into();
            return Ok(Loaded {
                roots: vec![o.clone()],
                objects: vec![o],
                header: Header::default(),
            });
        }
        if bytes.len() < 12 || bytes[..12] != FILE_IDENTIFIER {
            return Err(LoadError::file(
                "not an M3G file (bad file identifier) nor a PNG",
            ));
        }
        objects::parse_file(self, bytes)
    }

    /// The canonical path of the file a relative or `file://` reference names, refused
    /// when it leaves the base folder (unless allowed).
    fn locate(&self, uri: &str, path: &Path) -> LoadResult<PathBuf> {
        let canonical = self
            .fs
            .canonicalize(path)
            .map_err(|e| LoadError::file(format!("cannot read {}: {e}", path.display())))?;
        if !self.allow_outside {
            let inside = match &self.base {
                Some(b) => self
                    .fs
                    .canonicalize(b)
                    .is_ok_and(|b| canonical.starts_with(b)),
                None => false,
            };
            if !inside {
                return Err(LoadError::file(format!(
                    "external reference {uri:?} leads to {}, outside the folder of the referencing file (Loader::allow_outside_references permits it)",
                    canonical.display()
                )));
            }
        }
        Ok(canonical)
    }

    /// Loads the target of an external reference (once per load) and returns its first
    /// root.
    pub(crate) fn resolve(&mut self, uri: &str) -> LoadResult<Object3D> {
        let relative = !uri.contains(':') && !uri.starts_with('/');
        let target = if let (true, Some(base)) = (relative, &self.base) {
            Some(self.locate(uri, &base.join(uri))?)
        } else if let Some(path) = uri
            .strip_prefix("file://")
            .filter(|_| self.resolver.is_none())
        {
            Some(self.locate(uri, Path::new(path))?)
        } else {
            None
        };
        let key = match &target {
            Some(p) => p.display().to_string(),
            None => uri.to_string(),
        };
        if let Some(o) = self.cache.get(&key) {
            return Ok(o.clone());
        }
        if self.active.contains(&key) {
            return Err(LoadError::file(format!(
                "external reference loop: {uri:?} refers back to a file being loaded"
            )));
        }
        let (bytes, base) = if let Some(p) = &target {
            (self.read(p)?, p.parent().map(Path::to_path_buf))
        } else if let Some(r) = &self.resolver {
            let b = r(uri).map_err(|e| LoadError::file(format!("cannot resolve {uri:?}: {e}")))?;
            self.charge(b.len() as u64, || format!("external reference {uri:?}"))?;
            (b, self.base.clone())
        } else {
            return Err(LoadError::file(format!(
                "cannot resolve external reference {uri:?}: no base folder or resolver"
            )));
        };
        if !bytes.starts_with(&PNG_SIGNATURE) && !bytes.starts_with(&FILE_IDENTIFIER) {
            return Err(LoadError::file(format!(
                "external reference {uri:?} is neither M3G nor PNG"
            )));
        }
        let saved = std::mem::replace(&mut self.base, base);
        let r = self.load_keyed(&bytes, key.clone());
        self.base = saved;
        let loaded = r.map_err(|mut e| {
            e.message = format!("in external reference {uri:?}: {}", e.message);
            e
        })?;
        let first =
            loaded.roots.into_iter().next().ok_or_else(|| {
                LoadError::file(format!("external reference {uri:?} has no objects"))
            })?;
        self.cache.insert(key, first.clone());
        Ok(first)
    }
}

/// Adler-32 as zlib computes it.
pub fn adler32(data: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for chunk in data.chunks(5552) {
        for &x in chunk {
            a += x as u32;
            b += a;
        }
        a %= 65521;
        b %= 65521;
    }
    (b << 16) | a
}

/// A set of object indices (for tests of what got referenced).
pub(crate) type IndexSet = HashSet<u32>;
