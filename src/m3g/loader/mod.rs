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
//! by deflate's maximum ratio, and mutable images (which carry no pixels) are capped at
//! [`MAX_MUTABLE_IMAGE_PIXELS`].

mod objects;
mod png;
mod render;

use std::collections::HashSet;
use std::fmt;
use std::path::{Path, PathBuf};

pub use render::{render_roots, RenderTarget};

use super::Object3D;

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

/// A load failure (Java's `IOException`): where it happened and why.
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

/// The result of a load.
pub type LoadResult<T> = std::result::Result<T, LoadError>;

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

/// The M3G Loader.
///
/// | Java | Rust |
/// |---|---|
/// | `Loader.load(byte[], int)` | [`Loader::load`] (slice the offset off) |
/// | `Loader.load(String)` | [`Loader::load_path`] (a file name) or [`Loader::load_bytes`] with a [resolver](Loader::with_resolver) |
#[derive(Default)]
pub struct Loader {
    base: Option<PathBuf>,
    resolver: Option<Box<Resolver>>,
    /// Files being loaded (loop detection).
    active: Vec<String>,
}

impl fmt::Debug for Loader {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Loader")
            .field("base", &self.base)
            .field("resolver", &self.resolver.is_some())
            .finish()
    }
}

impl Loader {
    /// A loader with no base folder and no resolver.
    pub fn new() -> Loader {
        Loader::default()
    }

    /// Resolves relative external references against `dir`.
    pub fn with_base_dir(mut self, dir: impl Into<PathBuf>) -> Loader {
        self.base = Some(dir.into());
        self
    }

    /// Resolves URIs that are not relative file names (or any URI when there is no base
    /// folder) through `f`.
    pub fn with_resolver(
        mut self,
        f: impl Fn(&str) -> std::io::Result<Vec<u8>> + 'static,
    ) -> Loader {
        self.resolver = Some(Box::new(f));
        self
    }

    /// `Loader.load(byte[], 0)`: the root objects of a .m3g or PNG file in memory. External
    /// references cannot be resolved (use a [`Loader`] with a resolver).
    pub fn load(bytes: &[u8]) -> LoadResult<Vec<Object3D>> {
        Ok(Loader::new().load_bytes(bytes)?.roots)
    }

    /// The root objects of the .m3g or PNG file at `path`; relative external references are
    /// resolved against its folder.
    pub fn load_path(path: impl AsRef<Path>) -> LoadResult<Vec<Object3D>> {
        Ok(Loader::new().load_file(path)?.roots)
    }

    /// Loads a file from disk (its folder becomes the base for relative references).
    pub fn load_file(&mut self, path: impl AsRef<Path>) -> LoadResult<Loaded> {
        let path = path.as_ref();
        let bytes = std::fs::read(path)
            .map_err(|e| LoadError::file(format!("cannot read {}: {e}", path.display())))?;
        let saved = self.base.take();
        self.base = Some(
            path.parent()
                .map(Path::to_path_buf)
                .unwrap_or_else(|| PathBuf::from(".")),
        );
        let key = std::fs::canonicalize(path)
            .unwrap_or_else(|_| path.to_path_buf())
            .display()
            .to_string();
        let r = self.load_keyed(&bytes, key);
        self.base = saved;
        r
    }

    /// Loads bytes with this loader's base folder and resolver.
    pub fn load_bytes(&mut self, bytes: &[u8]) -> LoadResult<Loaded> {
        self.load_inner(bytes)
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
            let img = png::decode(bytes)?;
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

    /// Loads the target of an external reference and returns its first root.
    pub(crate) fn resolve(&mut self, uri: &str) -> LoadResult<Object3D> {
        let relative = !uri.contains(':') && !uri.starts_with('/');
        let (bytes, key, base) = if let (true, Some(base)) = (relative, self.base.clone()) {
            let p = base.join(uri);
            let b = std::fs::read(&p)
                .map_err(|e| LoadError::file(format!("cannot read {}: {e}", p.display())))?;
            let key = std::fs::canonicalize(&p)
                .unwrap_or_else(|_| p.clone())
                .display()
                .to_string();
            (b, key, p.parent().map(Path::to_path_buf))
        } else if let Some(path) = uri
            .strip_prefix("file://")
            .filter(|_| self.resolver.is_none())
        {
            let p = PathBuf::from(path);
            let b = std::fs::read(&p)
                .map_err(|e| LoadError::file(format!("cannot read {}: {e}", p.display())))?;
            (b, uri.to_string(), p.parent().map(Path::to_path_buf))
        } else if let Some(r) = &self.resolver {
            let b = r(uri).map_err(|e| LoadError::file(format!("cannot resolve {uri:?}: {e}")))?;
            (b, uri.to_string(), self.base.clone())
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
        let r = self.load_keyed(&bytes, key);
        self.base = saved;
        let loaded = r.map_err(|mut e| {
            e.message = format!("in external reference {uri:?}: {}", e.message);
            e
        })?;
        loaded
            .roots
            .into_iter()
            .next()
            .ok_or_else(|| LoadError::file(format!("external reference {uri:?} has no objects")))
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
