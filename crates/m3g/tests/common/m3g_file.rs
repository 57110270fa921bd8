//! Building `.m3g` files byte by byte, for the Loader tests (`crates/m3g/tests/m3g_loader.rs`,
//! `crates/m3g/tests/m3g_hostile.rs` include it by path).

use m3g::loader::{adler32, FILE_IDENTIFIER};

/// A section of `objects` stored with compression `scheme` (0: none, 1: zlib), checksummed.
pub fn section(scheme: u8, objects: &[u8]) -> Vec<u8> {
    let stored = if scheme == 1 {
        miniz_oxide::deflate::compress_to_vec_zlib(objects, 6)
    } else {
        objects.to_vec()
    };
    let mut s = vec![scheme];
    s.extend_from_slice(&(stored.len() as u32 + 13).to_le_bytes());
    s.extend_from_slice(&(objects.len() as u32).to_le_bytes());
    s.extend_from_slice(&stored);
    let a = adler32(&s);
    s.extend_from_slice(&a.to_le_bytes());
    s
}

/// One object: its type, length and data.
pub fn object(ty: u8, data: &[u8]) -> Vec<u8> {
    let mut o = vec![ty];
    o.extend_from_slice(&(data.len() as u32).to_le_bytes());
    o.extend_from_slice(data);
    o
}

/// A file from sections of (compression scheme, objects), with a header object whose
/// TotalFileSize is right; `xrefs` flags external references.
pub fn file(xrefs: bool, sections: &[(u8, Vec<Vec<u8>>)]) -> Vec<u8> {
    let body: Vec<Vec<u8>> = sections
        .iter()
        .map(|(s, objs)| section(*s, &objs.concat()))
        .collect();
    let header_size = 12 + 13 + 5 + 12;
    let total = header_size + body.iter().map(Vec::len).sum::<usize>();
    let mut h = vec![1, 0, xrefs as u8];
    h.extend_from_slice(&(total as u32).to_le_bytes());
    h.extend_from_slice(&(total as u32).to_le_bytes());
    h.push(0);
    let mut f = FILE_IDENTIFIER.to_vec();
    f.extend(section(0, &object(0, &h)));
    for b in body {
        f.extend(b);
    }
    assert_eq!(f.len(), total);
    f
}

#[allow(dead_code)]
/// A mutable RGBA Image2D of `side`²: 27 bytes in the file, 4·side² bytes once loaded.
pub fn mutable_image(side: u32) -> Vec<u8> {
    let mut v = vec![0; 12];
    v.extend([100, 1]); // RGBA, mutable
    v.extend(side.to_le_bytes());
    v.extend(side.to_le_bytes());
    object(10, &v)
}
