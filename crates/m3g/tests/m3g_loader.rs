//! The M3G Loader and writer: hand-made files, corrupt input, a mutation test over the corpus,
//! save → load identity, and the corpus rendered against the reference images.

use std::path::{Path, PathBuf};
use std::time::Instant;

use m3g::loader::{adler32, render_roots, Loaded, RenderTarget, UserParameters, FILE_IDENTIFIER};
use m3g::writer::save;
use m3g::*;

#[path = "common/corpus.rs"]
mod corpus;

/// The corpus is required here: these tests fail, never skip, without it.
fn corpus_dir() -> PathBuf {
    corpus::corpus_path()
}

fn corpus() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(corpus_dir())
        .expect("the corpus folder")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "m3g"))
        .collect();
    v.sort();
    v
}

// ---------------------------------------------------------------------------------------
// Building files by hand.

#[path = "common/m3g_file.rs"]
mod m3g_file;
use m3g_file::{file, object, section};

fn o3d() -> Vec<u8> {
    vec![0; 12]
}
fn node_part() -> Vec<u8> {
    let mut v = o3d();
    v.extend([0, 0]); // no transforms
    v.extend([1, 1, 255, 0xFF, 0xFF, 0xFF, 0xFF, 0]);
    v
}
fn group(children: &[u32]) -> Vec<u8> {
    let mut v = node_part();
    v.extend((children.len() as u32).to_le_bytes());
    for c in children {
        v.extend(c.to_le_bytes());
    }
    object(9, &v)
}
fn le(v: u32) -> [u8; 4] {
    v.to_le_bytes()
}
fn f(v: f32) -> [u8; 4] {
    v.to_le_bytes()
}

/// The checklist's 86-byte test vector.
const MINIMAL: [u8; 86] = [
    0xab, 0x4a, 0x53, 0x52, 0x31, 0x38, 0x34, 0xbb, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x1e, 0x00, 0x00,
    0x00, 0x11, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x56, 0x00, 0x00,
    0x00, 0x56, 0x00, 0x00, 0x00, 0x00, 0xe9, 0x00, 0xed, 0x09, 0x00, 0x2c, 0x00, 0x00, 0x00, 0x1f,
    0x00, 0x00, 0x00, 0x09, 0x1a, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x01, 0xff, 0xff, 0xff, 0xff, 0xff, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x6c, 0x05, 0x2b, 0x37,
];

fn err_of(bytes: &[u8]) -> LoadError {
    match Loader::load(bytes) {
        Ok(r) => panic!("loaded {} roots from a bad file", r.len()),
        Err(Error::Io(e)) => e,
        Err(e) => panic!("not an IOException: {e}"),
    }
}

/// Rewrites the Adler-32 of the section starting at `at`.
fn fix_sum(b: &mut [u8], at: usize) {
    let len = u32::from_le_bytes(b[at + 1..at + 5].try_into().unwrap()) as usize;
    let s = adler32(&b[at..at + len - 4]);
    b[at + len - 4..at + len].copy_from_slice(&s.to_le_bytes());
}

#[test]
fn checklist_test_vector_loads_one_group() {
    let roots = Loader::load(&MINIMAL).unwrap();
    assert_eq!(roots.len(), 1);
    let g = roots[0].downcast::<Group>().unwrap();
    assert_eq!(g.child_count(), 0);
    assert!(g.is_rendering_enabled() && g.is_picking_enabled());
    assert_eq!(g.scope(), -1);
    assert_eq!(g.alpha_factor(), 1.0);
    // The compressed variant of the checklist.
    let mut c = FILE_IDENTIFIER.to_vec();
    c.extend([
        0x00, 0x1e, 0x00, 0x00, 0x00, 0x11, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x00, 0x00, 0x00, 0x01,
        0x00, 0x00, 0x4a, 0x00, 0x00, 0x00, 0x4a, 0x00, 0x00, 0x00, 0x00, 0xd1, 0x00, 0x45, 0x09,
        0x01, 0x20, 0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00, 0x78, 0x9c, 0xe3, 0x94, 0x62, 0x40,
        0x07, 0x8c, 0x8c, 0xff, 0x41, 0x00, 0xcc, 0x06, 0x00, 0x2c, 0x31, 0x05, 0x21, 0x22, 0x07,
        0x26, 0x5c,
    ]);
    let roots = Loader::load(&c).unwrap();
    assert!(roots[0].downcast::<Group>().is_some());
}

#[test]
fn checklist_negative_mutations_fail_with_a_clear_error() {
    // Checksum byte.
    let mut b = MINIMAL;
    b[84] ^= 1;
    let e = err_of(&b);
    assert!(e.to_string().contains("Adler-32"), "{e}");
    // Version 1.1.
    let mut b = MINIMAL;
    b[27] = 1;
    fix_sum(&mut b, 12);
    let e = err_of(&b);
    assert_eq!(e.field.as_deref(), Some("VersionNumber"), "{e}");
    // A Boolean = 2 (enableRendering of the group).
    let mut b = MINIMAL;
    b[70] = 2;
    fix_sum(&mut b, 42);
    let e = err_of(&b);
    assert_eq!(e.object, Some(2));
    assert_eq!(e.field.as_deref(), Some("enableRendering"), "{e}");
    assert!(
        e.to_string()
            .contains("object 2 (Group), field enableRendering"),
        "{e}"
    );
    // Scheme 2.
    let mut b = MINIMAL;
    b[42] = 2;
    fix_sum(&mut b, 42);
    assert!(err_of(&b).to_string().contains("CompressionScheme 2"));
    // Type 23.
    let mut b = MINIMAL;
    b[51] = 23;
    fix_sum(&mut b, 42);
    assert!(err_of(&b).to_string().contains("reserved"));
    // TotalFileSize ± 1.
    for d in [-1i32, 1] {
        let mut b = MINIMAL;
        b[29] = (86 + d) as u8;
        fix_sum(&mut b, 12);
        assert_eq!(err_of(&b).field.as_deref(), Some("TotalFileSize"));
    }
    // Truncation anywhere.
    for n in 0..86 {
        assert!(Loader::load(&MINIMAL[..n]).is_err());
    }
}

#[test]
fn hand_made_corrupt_objects_name_index_and_field() {
    // Self reference as child.
    let e = err_of(&file(false, &[(0, vec![group(&[2])])]));
    assert_eq!(
        (e.object, e.field.as_deref()),
        (Some(2), Some("children[0]"))
    );
    // Forward reference.
    let e = err_of(&file(false, &[(0, vec![group(&[3]), group(&[])])]));
    assert!(e.message.contains("forward"), "{e}");
    // Reference to the header.
    let e = err_of(&file(false, &[(1, vec![group(&[1])])]));
    assert!(e.message.contains("header"), "{e}");
    // Wrong type: a group whose child is a CompositingMode.
    let mut cm = o3d();
    cm.extend([1, 1, 1, 1, 68, 0]);
    cm.extend(f(0.0));
    cm.extend(f(0.0));
    let e = err_of(&file(false, &[(0, vec![object(6, &cm), group(&[2])])]));
    assert!(
        e.message.contains("is a CompositingMode, expected a Node"),
        "{e}"
    );
    // Two parents.
    let e = err_of(&file(
        false,
        &[(0, vec![group(&[]), group(&[2]), group(&[2])])],
    ));
    assert_eq!(
        (e.object, e.field.as_deref()),
        (Some(4), Some("children[0]"))
    );
    // -0.0 in a translation.
    let mut v = o3d();
    v.push(1);
    v.extend(le(0x8000_0000));
    v.extend(f(0.0));
    v.extend(f(0.0));
    for x in [1.0f32, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0] {
        v.extend(f(x));
    }
    v.push(0);
    v.extend([1, 1, 255, 0, 0, 0, 0, 0]);
    v.extend(le(0));
    let e = err_of(&file(false, &[(0, vec![object(9, &v)])]));
    assert_eq!(e.field.as_deref(), Some("translation[0]"));
    assert!(e.message.contains("-0.0"));
    // NaN, infinity and a denormal in a Material's shininess.
    for (bits, what) in [
        (0x7FC0_0000u32, "NaN"),
        (0x7F80_0000, "infinite"),
        (1, "denormal"),
    ] {
        let mut m = o3d();
        m.extend([0; 3 + 4 + 3 + 3]);
        m.extend(le(bits));
        m.push(0);
        let e = err_of(&file(false, &[(0, vec![object(13, &m)])]));
        assert_eq!(e.field.as_deref(), Some("shininess"));
        assert!(e.message.contains(what), "{e}");
    }
    // Shininess out of range (an API rejection).
    let mut m = o3d();
    m.extend([0; 13]);
    m.extend(f(129.0));
    m.push(0);
    let e = err_of(&file(false, &[(0, vec![object(13, &m)])]));
    assert_eq!(e.field.as_deref(), Some("shininess"));
    // Leftover bytes.
    let mut g = group(&[]);
    g.push(0);
    g[1] += 1;
    let e = err_of(&file(false, &[(0, vec![g])]));
    assert!(e.message.contains("left over"), "{e}");
    // A count that overruns: 0xFFFFFFFF children.
    let mut v = node_part();
    v.extend(le(u32::MAX));
    let e = err_of(&file(false, &[(0, vec![object(9, &v)])]));
    assert_eq!(e.field.as_deref(), Some("children"));
    // A huge immutable image with no data, and a huge mutable one.
    let mut im = o3d();
    im.extend([99, 0]);
    im.extend(le(60000));
    im.extend(le(60000));
    im.extend(le(0));
    im.extend(le(0));
    assert_eq!(
        err_of(&file(false, &[(0, vec![object(10, &im)])]))
            .field
            .as_deref(),
        Some("pixels")
    );
    let mut im = o3d();
    im.extend([99, 1]);
    im.extend(le(60000));
    im.extend(le(60000));
    assert!(err_of(&file(false, &[(0, vec![object(10, &im)])]))
        .message
        .contains("limit"));
    // Appearance layer is a signed byte: -63 loads, -64 (0xC0) does not.
    for (layer, ok) in [(0xC1u8, true), (0xC0, false), (63, true), (64, false)] {
        let mut a = o3d();
        a.push(layer);
        a.extend([0; 16]);
        a.extend(le(0));
        let r = Loader::load(&file(false, &[(0, vec![object(3, &a)])]));
        assert_eq!(r.is_ok(), ok, "layer byte {layer:#x}");
        if ok {
            let app = r.unwrap()[0].downcast::<Appearance>().unwrap();
            assert_eq!(app.layer(), layer as i8 as i32);
        }
    }
    // A file with only a header.
    let mut h = vec![1, 0, 0];
    h.extend(le(12 + 30));
    h.extend(le(12 + 30));
    h.push(0);
    let mut only = FILE_IDENTIFIER.to_vec();
    only.extend(section(0, &object(0, &h)));
    assert!(err_of(&only).message.contains("no objects"));
    // An external reference without hasExternalReferences, and a non-header in section 0.
    let e = err_of(&file(false, &[(0, vec![object(255, b"a.png\0")])]));
    assert!(e.message.contains("external references"), "{e}");
    // Zlib section whose UncompressedLength lies.
    let mut b = file(false, &[(1, vec![group(&[])])]);
    let at = 12 + 30;
    b[at + 5] += 1;
    fix_sum(&mut b, at);
    assert!(err_of(&b).field.as_deref() == Some("section 1"));
}

#[test]
fn field_layouts_load_as_specified() {
    // VertexArray (deltas), VertexBuffer (bias before scale), TriangleStripArray, Background
    // (depth clear before color clear), Material colors, user parameters.
    let mut va = o3d();
    va.extend([1, 3, 1]); // bytes, 3 comps, delta encoding
    va.extend(2u16.to_le_bytes());
    va.extend([0, 127, 10, 0xFF, 0x81, 1]); // deltas: second = (-1, 0, 11)
    let mut vb = o3d();
    vb.extend([10, 20, 30, 40]); // RGBA
    vb.extend(le(2));
    for x in [1.0f32, 2.0, 3.0, 0.5] {
        vb.extend(f(x)); // bias x y z, then scale
    }
    vb.extend(le(0));
    vb.extend(le(0));
    vb.extend(le(0));
    let mut tsa = o3d();
    tsa.push(1); // implicit, byte start
    tsa.push(1);
    tsa.extend(le(1));
    tsa.extend(le(3));
    let mut bg = o3d();
    bg.extend([1, 2, 3, 4]);
    bg.extend(le(0));
    bg.extend([32, 33]);
    bg.extend([0; 16]);
    bg.extend([1, 0]); // depth clear on, color clear off
    let mut mat = o3d();
    // one user parameter
    mat.truncate(8);
    mat.extend(le(1));
    mat.extend(le(7));
    mat.extend(le(2));
    mat.extend([0xAB, 0xCD]);
    mat.extend([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13]);
    mat.extend(f(10.0));
    mat.push(1);
    let b = file(
        false,
        &[(
            1,
            vec![
                object(20, &va),
                object(21, &vb),
                object(11, &tsa),
                object(4, &bg),
                object(13, &mat),
            ],
        )],
    );
    let l = Loader::new().load_bytes(&b).unwrap();
    assert_eq!(l.roots.len(), 4); // the VertexArray is referenced
    let va = l.objects[0].downcast::<VertexArray>().unwrap();
    assert_eq!(va.get_bytes(0, 2).unwrap(), vec![0, 127, 10, -1, 0, 11]);
    let vb = l.objects[1].downcast::<VertexBuffer>().unwrap();
    assert_eq!(vb.get_positions().1, [0.5, 1.0, 2.0, 3.0]);
    assert_eq!(vb.default_color(), Color(0x280A141E));
    let ib = l.objects[2].downcast::<IndexBuffer>().unwrap();
    assert_eq!(ib.indices(), vec![1, 2, 3]);
    let bg = l.objects[3].downcast::<Background>().unwrap();
    assert!(bg.is_depth_clear_enabled() && !bg.is_color_clear_enabled());
    assert_eq!(bg.color(), Color(0x04010203));
    assert_eq!(
        (bg.image_mode_x(), bg.image_mode_y()),
        (ImageMode::Border, ImageMode::Repeat)
    );
    let m = l.objects[4].downcast::<Material>().unwrap();
    assert_eq!(m.color(MaterialColor::AMBIENT).unwrap(), Color(0x010203));
    assert_eq!(m.color(MaterialColor::DIFFUSE).unwrap(), Color(0x07040506));
    assert_eq!(m.color(MaterialColor::SPECULAR).unwrap(), Color(0x0B0C0D));
    assert!(m.is_vertex_color_tracking_enabled());
    let p = m.user_object().unwrap();
    let p = p.downcast_ref::<UserParameters>().unwrap();
    assert_eq!(p.get(&7), Some(&vec![0xAB, 0xCD]));
    // And the writer keeps it all.
    let again = Loader::new()
        .load_bytes(&save(&l.roots, true).unwrap())
        .unwrap();
    assert_eq!(fingerprints(&again), fingerprints(&l));
}

#[test]
fn png_formats_follow_the_m3g_rule() {
    use image::{ExtendedColorType, ImageEncoder};
    let enc = |px: &[u8], t: ExtendedColorType| {
        let mut out = Vec::new();
        image::codecs::png::PngEncoder::new(&mut out)
            .write_image(px, 2, 1, t)
            .unwrap();
        out
    };
    let cases = [
        (enc(&[1, 2], ExtendedColorType::L8), ImageFormat::Luminance),
        (
            enc(&[1, 2, 3, 4], ExtendedColorType::La8),
            ImageFormat::LuminanceAlpha,
        ),
        (
            enc(&[1, 2, 3, 4, 5, 6], ExtendedColorType::Rgb8),
            ImageFormat::Rgb,
        ),
        (
            enc(&[1, 2, 3, 4, 5, 6, 7, 8], ExtendedColorType::Rgba8),
            ImageFormat::Rgba,
        ),
    ];
    for (png, format) in cases {
        let r = Loader::load(&png).unwrap();
        let img = r[0].downcast::<Image2D>().unwrap();
        assert_eq!(img.format(), format);
        assert!(!img.is_mutable());
        assert_eq!((img.width(), img.height()), (2, 1));
    }
    // The corpus PNGs: one truecolour, one palette, both RGB.
    for name in ["memory.png", "robot_texture.png"] {
        let r = Loader::load_path(corpus_dir().join(name)).unwrap();
        assert_eq!(
            r[0].downcast::<Image2D>().unwrap().format(),
            ImageFormat::Rgb
        );
    }
    assert!(Loader::load(b"\x89PNG\r\n\x1a\nbroken").is_err());
}

#[test]
fn external_references_resolve_relative_and_through_a_resolver() {
    let dir = corpus_dir();
    let l = Loader::new().load_file(dir.join("memory.m3g")).unwrap();
    assert!(l.objects.iter().any(|o| o.downcast::<Image2D>().is_some()));
    // From bytes without a base: an error naming the reference.
    let bytes = std::fs::read(dir.join("memory.m3g")).unwrap();
    let e = err_of(&bytes);
    assert_eq!(e.class, Some("ExternalReference"), "{e}");
    // A resolver.
    let d2 = dir.clone();
    let l2 = Loader::new()
        .with_resolver(move |uri| std::fs::read(d2.join(uri)))
        .load_bytes(&bytes)
        .unwrap();
    assert_eq!(l2.objects.len(), l.objects.len());
    // A loop: a file that references itself.
    let tmp = std::env::temp_dir().join(format!("m3g-loop-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let me = file(
        true,
        &[(0, vec![object(255, b"self.m3g\0")]), (0, vec![group(&[])])],
    );
    std::fs::write(tmp.join("self.m3g"), &me).unwrap();
    let e = Loader::load_path(tmp.join("self.m3g")).unwrap_err();
    assert!(e.message().contains("loop"), "{e}");
    // A reference to something that is neither M3G nor PNG.
    std::fs::write(tmp.join("x.jpg"), b"\xFF\xD8\xFF\xE0 not a png").unwrap();
    let other = file(
        true,
        &[(0, vec![object(255, b"x.jpg\0")]), (0, vec![group(&[])])],
    );
    std::fs::write(tmp.join("other.m3g"), &other).unwrap();
    let e = Loader::load_path(tmp.join("other.m3g")).unwrap_err();
    assert!(e.message().contains("neither M3G nor PNG"), "{e}");
    let _ = std::fs::remove_dir_all(&tmp);
}

// ---------------------------------------------------------------------------------------
// The corpus.

#[test]
fn every_corpus_file_loads() {
    let files = corpus();
    assert_eq!(files.len(), 11);
    for p in files {
        let t = Instant::now();
        let l = Loader::new()
            .load_file(&p)
            .unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        assert!(!l.roots.is_empty());
        assert_eq!(
            l.roots
                .iter()
                .filter(|r| r.downcast::<World>().is_some())
                .count(),
            1,
            "{}",
            p.display()
        );
        eprintln!(
            "{}: {} objects, {} roots, {:?}",
            p.file_name().unwrap().to_string_lossy(),
            l.objects.len(),
            l.roots.len(),
            t.elapsed()
        );
    }
}

#[test]
fn corpus_mutations_never_panic() {
    // Deterministic byte flips and truncations; every result must be Ok or a LoadError.
    let mut seed = 0x2545F4914F6CDD1Du64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    let mut loaded = 0;
    for p in corpus() {
        let orig = std::fs::read(&p).unwrap();
        let dir = p.parent().unwrap().to_path_buf();
        for k in 0..120 {
            let mut b = orig.clone();
            match k % 4 {
                0 => b.truncate(rnd() as usize % b.len()),
                1 => {
                    let i = rnd() as usize % b.len();
                    b[i] ^= 1 << (rnd() % 8);
                }
                2 => {
                    // Flip a byte and repair the checksums so the object parser sees it.
                    let i = 12 + rnd() as usize % (b.len() - 12);
                    b[i] = rnd() as u8;
                    repair_sums(&mut b);
                }
                _ => b = mutate_objects(&orig, rnd(), rnd() as u8),
            }
            let d = dir.clone();
            let r = std::panic::catch_unwind(|| {
                Loader::new()
                    .with_base_dir(d)
                    .load_bytes(&b)
                    .map(|l| l.objects.len())
            });
            match r {
                Ok(Ok(_)) => loaded += 1,
                Ok(Err(e)) => assert!(!e.to_string().is_empty()),
                Err(_) => panic!("{}: mutation {k} panicked", p.display()),
            }
        }
    }
    eprintln!("{loaded} mutated files still loaded");
}

/// The file re-encoded with every section uncompressed and one byte of the object data
/// (after inflating) replaced: reaches the object parser in zlib files too.
fn mutate_objects(orig: &[u8], at: u64, value: u8) -> Vec<u8> {
    let mut sections = Vec::new();
    let mut p = 12;
    while p + 13 <= orig.len() {
        let len = u32::from_le_bytes(orig[p + 1..p + 5].try_into().unwrap()) as usize;
        let body = &orig[p + 9..p + len - 4];
        let data = if orig[p] == 1 {
            miniz_oxide::inflate::decompress_to_vec_zlib(body).unwrap()
        } else {
            body.to_vec()
        };
        sections.push(data);
        p += len;
    }
    let total: usize = sections.iter().map(Vec::len).sum();
    let mut k = (at % total as u64) as usize;
    for s in sections.iter_mut().skip(1) {
        if k < s.len() {
            s[k] = value;
            break;
        }
        k -= s.len().min(k);
    }
    let mut out = FILE_IDENTIFIER.to_vec();
    for s in &sections {
        out.extend(section(0, s));
    }
    let n = out.len() as u32;
    // TotalFileSize sits at byte 12 + 9 (section header) + 5 (object header) + 3.
    out[29..33].copy_from_slice(&n.to_le_bytes());
    fix_sum(&mut out, 12);
    out
}

/// Recomputes the Adler-32 of every uncompressed section that is still well framed.
fn repair_sums(b: &mut [u8]) {
    let mut at = 12;
    while at + 13 <= b.len() {
        let len = u32::from_le_bytes(b[at + 1..at + 5].try_into().unwrap()) as usize;
        if len < 13 || at + len > b.len() {
            return;
        }
        if b[at] == 0 {
            fix_sum(b, at);
        }
        at += len;
    }
}

/// A description of every object through the public API, sorted (save order differs).
fn fingerprints(l: &Loaded) -> Vec<String> {
    let r = |x: f32| format!("{:.4}", x);
    let mut v: Vec<String> = l
        .objects
        .iter()
        .map(|o| {
            let mut s = format!(
                "{} id={} tracks={} refs={}",
                o.class_name(),
                o.user_id(),
                o.animation_track_count(),
                o.get_references().len()
            );
            if let Some(n) = o.downcast::<Node>() {
                let m = n.get_composite_transform().get();
                s += &format!(
                    " node r={} p={} a={} s={} m={:?}",
                    n.is_rendering_enabled(),
                    n.is_picking_enabled(),
                    r(n.alpha_factor()),
                    n.scope(),
                    m.iter().map(|&x| r(x)).collect::<Vec<_>>()
                );
            }
            if let Some(g) = o.downcast::<Group>() {
                s += &format!(" children={}", g.child_count());
            }
            if let Some(va) = o.downcast::<VertexArray>() {
                s += &format!(
                    " va {}x{}x{} {:?}",
                    va.vertex_count(),
                    va.component_count(),
                    va.component_type(),
                    if va.component_type() == 1 {
                        va.get_bytes(0, va.vertex_count())
                            .unwrap()
                            .iter()
                            .map(|&x| x as i32)
                            .collect::<Vec<_>>()
                    } else {
                        va.get_shorts(0, va.vertex_count())
                            .unwrap()
                            .iter()
                            .map(|&x| x as i32)
                            .collect()
                    }
                );
            }
            if let Some(vb) = o.downcast::<VertexBuffer>() {
                s += &format!(
                    " vb n={} pos={:?} dc={:x}",
                    vb.vertex_count(),
                    vb.get_positions().1.map(r),
                    vb.default_color()
                );
                for k in 0..NUM_TEXTURE_UNITS {
                    let (a, sb) = vb.get_tex_coords(k).unwrap();
                    s += &format!(
                        " tc{k}={} {:?}",
                        a.is_some(),
                        sb.iter().map(|&x| r(x)).collect::<Vec<_>>()
                    );
                }
            }
            if let Some(ib) = o.downcast::<IndexBuffer>() {
                s += &format!(" ib {:?}", ib.indices());
            }
            if let Some(img) = o.downcast::<Image2D>() {
                let p = img.pixels();
                s += &format!(
                    " img {} {}x{} m={} sum={}",
                    img.format().as_raw(),
                    img.width(),
                    img.height(),
                    img.is_mutable(),
                    adler32(&p)
                );
            }
            if let Some(m) = o.downcast::<Material>() {
                for t in [
                    MaterialColor::AMBIENT,
                    MaterialColor::DIFFUSE,
                    MaterialColor::EMISSIVE,
                    MaterialColor::SPECULAR,
                ] {
                    s += &format!(" {:x}", m.color(t).unwrap());
                }
                s += &format!(
                    " sh={} tr={}",
                    r(m.shininess()),
                    m.is_vertex_color_tracking_enabled()
                );
            }
            if let Some(c) = o.downcast::<Camera>() {
                let (t, p) = c.get_projection_params();
                s += &format!(" cam {} {:?}", t.as_raw(), p.map(|p| p.map(r)));
            }
            if let Some(li) = o.downcast::<Light>() {
                s += &format!(
                    " light {} {:x} {} {} {}",
                    li.mode().as_raw(),
                    li.color(),
                    r(li.intensity()),
                    r(li.spot_angle()),
                    r(li.spot_exponent())
                );
            }
            if let Some(a) = o.downcast::<Appearance>() {
                s += &format!(
                    " app layer={} cm={} pm={} mat={} tex0={}",
                    a.layer(),
                    a.compositing_mode().is_some(),
                    a.polygon_mode().is_some(),
                    a.material().is_some(),
                    a.texture(0).unwrap().is_some()
                );
            }
            if let Some(t) = o.downcast::<Texture2D>() {
                s += &format!(
                    " tex {} {} {} {} {} {:x}",
                    t.wrapping_s().as_raw(),
                    t.wrapping_t().as_raw(),
                    t.level_filter().as_raw(),
                    t.image_filter().as_raw(),
                    t.blending().as_raw(),
                    t.blend_color()
                );
            }
            if let Some(p) = o.downcast::<PolygonMode>() {
                s += &format!(
                    " pm {} {} {}",
                    p.culling().as_raw(),
                    p.shading().as_raw(),
                    p.winding().as_raw()
                );
            }
            if let Some(c) = o.downcast::<CompositingMode>() {
                s += &format!(
                    " cm {} {} {} {}",
                    c.blending().as_raw(),
                    r(c.alpha_threshold()),
                    c.is_depth_test_enabled(),
                    c.is_depth_write_enabled()
                );
            }
            if let Some(b) = o.downcast::<Background>() {
                s += &format!(
                    " bg {:x} {} {} {}",
                    b.color(),
                    b.is_color_clear_enabled(),
                    b.is_depth_clear_enabled(),
                    b.image().is_some()
                );
            }
            if let Some(k) = o.downcast::<KeyframeSequence>() {
                s += &format!(
                    " kf {} {} {} {} {}..{}",
                    k.keyframe_count(),
                    k.component_count(),
                    k.interpolation_type().as_raw(),
                    k.duration(),
                    k.valid_range_first(),
                    k.valid_range_last()
                );
                for i in 0..k.keyframe_count() {
                    let (t, v) = k.get_keyframe(i).unwrap();
                    s += &format!(" {t}:{:?}", v.iter().map(|&x| r(x)).collect::<Vec<_>>());
                }
            }
            if let Some(t) = o.downcast::<AnimationTrack>() {
                s += &format!(
                    " track {} ctl={}",
                    t.target_property().as_raw(),
                    t.controller().is_some()
                );
            }
            if let Some(c) = o.downcast::<AnimationController>() {
                s += &format!(
                    " ctl {} {} {} {}",
                    r(c.speed()),
                    r(c.weight()),
                    c.active_interval_start(),
                    c.active_interval_end()
                );
            }
            if let Some(sm) = o.downcast::<SkinnedMesh>() {
                s += &format!(" skin {}", sm.skeleton().child_count());
            }
            s
        })
        .collect();
    v.sort();
    v
}

#[test]
fn save_then_load_is_an_identity_over_the_corpus() {
    for p in corpus() {
        let l = Loader::new().load_file(&p).unwrap();
        for compress in [false, true] {
            let bytes = save(&l.roots, compress).unwrap();
            let again = Loader::new()
                .load_bytes(&bytes)
                .unwrap_or_else(|e| panic!("{} (compress {compress}): {e}", p.display()));
            assert_eq!(again.roots.len(), l.roots.len(), "{}", p.display());
            assert_eq!(again.objects.len(), l.objects.len(), "{}", p.display());
            let (a, b) = (fingerprints(&l), fingerprints(&again));
            for (x, y) in a.iter().zip(&b) {
                assert_eq!(x, y, "{}", p.display());
            }
            // Saving again gives a file of the same size (floats such as the orientation
            // axis may differ in their last bits after the angle-axis round trip).
            if !compress {
                let b2 = save(&again.roots, false).unwrap();
                assert_eq!(b2.len(), bytes.len(), "{}", p.display());
            }
        }
    }
}

#[test]
fn writer_authors_fog_sprite_morphing_and_alignment() {
    // A World with a camera, a Fog appearance, a Sprite3D, a MorphingMesh with two targets,
    // an aligned node, a keyframe-animated group and user parameters; zlib and plain.
    let va = VertexArray::new(3, 3, 2).unwrap();
    va.set_shorts(0, &[0, 0, 0, 1, 0, 0, 0, 1, 0]).unwrap();
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&va), 0.5, Some(&[1.0, 2.0, 3.0]))
        .unwrap();
    let tc = VertexArray::new(3, 2, 1).unwrap();
    tc.set_bytes(0, &[0, 0, 1, 0, 0, 1]).unwrap();
    vb.set_tex_coords(0, Some(&tc), 2.0, Some(&[0.5, 0.25]))
        .unwrap();
    let targets: Vec<VertexBuffer> = (0..2)
        .map(|k| {
            let a = VertexArray::new(3, 3, 1).unwrap();
            a.set_bytes(0, &[k, 0, 0, 0, k, 0, 0, 0, k]).unwrap();
            let t = VertexBuffer::new();
            t.set_positions(Some(&a), 1.0, None).unwrap();
            t
        })
        .collect();
    let ib = TriangleStripArray::new_implicit(0, &[3])
        .unwrap()
        .as_index_buffer();
    let fog = Fog::new();
    fog.set_mode(FogMode::Exponential);
    fog.set_density(0.25).unwrap();
    fog.set_color(Color(0x123456));
    let app = Appearance::new();
    app.set_fog(Some(&fog));
    app.set_layer(-5).unwrap();
    let img = Image2D::with_pixels(ImageFormat::Rgba, 2, 2, &[9; 16]).unwrap();
    let tex = Texture2D::new(&img).unwrap();
    tex.set_translation(0.5, 0.0, 0.0);
    app.set_texture(0, Some(&tex)).unwrap();
    let mm = MorphingMesh::new(&vb, &targets, &ib, Some(&app)).unwrap();
    mm.set_weights(&[0.25, 0.75]).unwrap();
    let sprite = Sprite3D::new(true, &img, Some(&app));
    sprite.set_crop(1, 1, -2, 2).unwrap();
    let cam = Camera::new();
    cam.set_perspective(60.0, 0.75, 0.5, 100.0).unwrap();
    cam.set_orientation(30.0, 0.0, 1.0, 0.0).unwrap();
    let world = World::new();
    let target = Group::new();
    world.add_child(&target).unwrap();
    world.add_child(&cam).unwrap();
    world.add_child(&mm).unwrap();
    world.add_child(&sprite).unwrap();
    sprite
        .set_alignment(
            Some(&target.as_node()),
            AlignTarget::Origin,
            None,
            AlignTarget::None,
        )
        .unwrap();
    world.set_active_camera(&cam);
    let ks = KeyframeSequence::new(2, 3, Interpolation::Linear).unwrap();
    ks.set_keyframe(0, 0, &[0.0, 0.0, 0.0]).unwrap();
    ks.set_keyframe(1, 100, &[1.0, 2.0, 3.0]).unwrap();
    ks.set_duration(200).unwrap();
    let track = AnimationTrack::new(&ks, AnimationProperty::Translation).unwrap();
    let ctl = AnimationController::new();
    ctl.set_active_interval(0, 500).unwrap();
    track.set_controller(Some(&ctl));
    target.add_animation_track(&track).unwrap();
    let mut params = UserParameters::new();
    params.insert(3, b"hello".to_vec());
    world.set_user_object(Some(std::rc::Rc::new(params)));
    world.set_user_id(77);
    for compress in [false, true] {
        let bytes = save(&[world.as_object3d()], compress).unwrap();
        let l = Loader::new().load_bytes(&bytes).unwrap();
        assert_eq!(l.roots.len(), 1);
        let w = l.roots[0].downcast::<World>().unwrap();
        assert_eq!(w.user_id(), 77);
        let p = w.user_object().unwrap();
        assert_eq!(p.downcast_ref::<UserParameters>().unwrap()[&3], b"hello");
        assert_eq!(w.child_count(), 4);
        let mm2 = w.child(2).unwrap().downcast::<MorphingMesh>().unwrap();
        assert_eq!(mm2.weights(), vec![0.25, 0.75]);
        assert_eq!(mm2.morph_target_count(), 2);
        let app2 = mm2.as_mesh().appearance(0).unwrap().unwrap();
        assert_eq!(app2.layer(), -5);
        let fog2 = app2.fog().unwrap();
        assert_eq!(
            (fog2.mode(), fog2.density(), fog2.color()),
            (FogMode::Exponential, 0.25, Color(0x123456))
        );
        let sp = w.child(3).unwrap().downcast::<Sprite3D>().unwrap();
        assert!(sp.is_scaled());
        assert_eq!(
            [sp.crop_x(), sp.crop_y(), sp.crop_width(), sp.crop_height()],
            [1, 1, -2, 2]
        );
        assert_eq!(
            sp.alignment_target(AlignTarget::ZAxis).unwrap(),
            AlignTarget::Origin
        );
        assert_eq!(
            sp.alignment_reference(AlignTarget::ZAxis).unwrap().unwrap(),
            w.child(0).unwrap()
        );
        let cam2 = w.active_camera().unwrap();
        assert_eq!(
            cam2.get_projection_params(),
            (Projection::Perspective, Some([60.0, 0.75, 0.5, 100.0]))
        );
        let o = cam2.get_orientation();
        assert!(
            (o[0] - 30.0).abs() < 1e-3 && (o[2] - 1.0).abs() < 1e-5,
            "{o:?}"
        );
        let (_, sb) = mm2.as_mesh().vertex_buffer().get_tex_coords(0).unwrap();
        assert_eq!(sb, vec![2.0, 0.5, 0.25]);
        // The animation survives: animate moves the target group.
        w.animate(50).unwrap();
        let t = w.child(0).unwrap().get_translation();
        assert!(
            (t[0] - 0.5).abs() < 1e-5 && (t[2] - 1.5).abs() < 1e-5,
            "{t:?}"
        );
        let again = Loader::new()
            .load_bytes(&save(&l.roots, compress).unwrap())
            .unwrap();
        assert_eq!(fingerprints(&again), fingerprints(&l));
    }
    // A cycle (a node aligned to its own parent) cannot be written.
    let g = Group::new();
    let child = Group::new();
    g.add_child(&child).unwrap();
    child
        .set_alignment(
            Some(&g.as_node()),
            AlignTarget::Origin,
            None,
            AlignTarget::None,
        )
        .unwrap();
    assert!(save(&[g.as_object3d()], false).is_err());
}

// ---------------------------------------------------------------------------------------
// Rendering against the reference images.

struct Diff {
    max: u8,
    mean: f64,
    psnr: f64,
    over8: usize,
}

fn compare(ours: &[u8], reference: &Path) -> Diff {
    let r = image::open(reference).unwrap().to_rgb8();
    let r = r.as_raw();
    assert_eq!(r.len(), ours.len());
    let (mut max, mut sum, mut sq, mut over8) = (0u8, 0u64, 0u64, 0usize);
    for (a, b) in ours.chunks(3).zip(r.chunks(3)) {
        let mut pmax = 0;
        for k in 0..3 {
            let d = a[k].abs_diff(b[k]);
            pmax = pmax.max(d);
            sum += d as u64;
            sq += d as u64 * d as u64;
        }
        max = max.max(pmax);
        if pmax > 8 {
            over8 += 1;
        }
    }
    let mse = sq as f64 / ours.len() as f64;
    Diff {
        max,
        mean: sum as f64 / ours.len() as f64,
        psnr: if mse == 0.0 {
            f64::INFINITY
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
        over8,
    }
}

/// Renders every corpus reference image's file at its time and compares it with the
/// reference under the MANIFEST's tolerance (≤ 1 % of pixels off by more than 8, mean ≤ 1.0).
///
/// With lit colors clamped after texturing, as Mesa (which made the references) does, every
/// image must pass. With the specification's clamp right after lighting, every image but
/// wizzer-teapot_t0 must pass: its specular highlight lies above 1 and modulates a texture,
/// so the references show a brighter patch there (825 pixels over 8, 1.07 %). That patch must
/// be the only difference, so the spec-mode image must pass once those pixels are excused.
#[test]
fn corpus_renders_compare_with_the_reference_images() {
    let refs = corpus_dir().join("reference");
    let mut names: Vec<String> = std::fs::read_dir(&refs)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    names.sort();
    assert_eq!(names.len(), 15);
    eprintln!("| image | load ms | objects | clamp | max | mean | PSNR dB | px >8 | pass |");
    eprintln!("|---|---|---|---|---|---|---|---|---|");
    let mut failures = Vec::new();
    for n in names {
        let (stem, t) = n.trim_end_matches(".png").rsplit_once("_t").unwrap();
        let t: i32 = t.parse().unwrap();
        let start = Instant::now();
        let l = Loader::new()
            .load_file(corpus_dir().join(format!("{stem}.m3g")))
            .unwrap();
        let load_ms = start.elapsed().as_secs_f64() * 1000.0;
        let mut images = Vec::new();
        for (clamp_after_lighting, mode) in [(false, "late"), (true, "spec")] {
            let img = render_roots(
                &l.roots,
                t,
                240,
                320,
                clamp_after_lighting,
                RenderTarget::Graphics,
            )
            .unwrap();
            let d = compare(&img, &refs.join(&n));
            let pass = d.over8 <= 768 && d.mean <= 1.0;
            eprintln!(
                "| {n} | {load_ms:.2} | {} | {mode} | {} | {:.3} | {:.2} | {} | {} |",
                l.objects.len(),
                d.max,
                d.mean,
                d.psnr,
                d.over8,
                if pass { "yes" } else { "no" }
            );
            if !pass && (mode == "late" || n != "wizzer-teapot_t0.png") {
                failures.push(format!("{n} ({mode})"));
            }
            images.push(img);
        }
        if n == "wizzer-teapot_t0.png" {
            // The two modes differ only where a lit channel exceeded 1; excusing those
            // pixels, the spec-mode image is within tolerance too.
            let (late, spec) = (&images[0], &images[1]);
            let r = image::open(refs.join(&n)).unwrap().to_rgb8();
            let unexplained = (0..late.len() / 3)
                .filter(|&i| {
                    let (a, b) = (&late[3 * i..3 * i + 3], &spec[3 * i..3 * i + 3]);
                    let want = &r.as_raw()[3 * i..3 * i + 3];
                    a == b && (0..3).any(|k| b[k].abs_diff(want[k]) > 8)
                })
                .count();
            assert!(unexplained <= 768, "{unexplained}");
        }
        if let Ok(dir) = std::env::var("M3G_RENDER_DIR") {
            image::save_buffer(
                Path::new(&dir).join(&n),
                &images[0],
                240,
                320,
                image::ExtendedColorType::Rgb8,
            )
            .unwrap();
        }
    }
    assert!(failures.is_empty(), "regressed: {failures:?}");
}
