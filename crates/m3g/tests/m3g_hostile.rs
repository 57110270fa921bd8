//! Hostile `.m3g` input (issue 19, items 5-7): scene graphs deeper than any stack, files
//! that ask for far more memory than they hold, and external references that loop, fan
//! out, or point at FIFOs and devices. Every input is generated here; each case must end
//! in `Ok` or a clear `LoadError`, never a crash, hang or runaway allocation.

use std::path::PathBuf;

use std::sync::mpsc;
use std::time::Duration;

use m3g::loader::{render_roots, LoadError, Loader, MemoryFileSystem, RenderTarget};
use m3g::Error;
use m3g::*;

/// The fuzz targets' rendering of what loaded, compiled and run here too so that it
/// cannot rot between fuzzing runs (which need nightly and cargo-fuzz).
#[path = "../../../fuzz/fuzz_targets/render.rs"]
mod fuzz_render;

/// A fresh temporary folder for one test.
fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("m3g-hostile-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Item 5: every traversal over a 100 000-deep Group chain (build, save, drop, load,
/// render, light collection, animate, find, pick, duplicate, Debug, drop of the loaded
/// graph) runs on a 1 MiB stack; the rendered square is lit red.
#[test]
fn a_group_chain_100000_deep_loads_renders_and_drops_on_a_small_stack() {
    on_small_stack(|| {
        let world = deep_world();
        let bytes = writer::save(&[world.as_object3d()], false).unwrap();
        drop(world);
        let roots = Loader::load(&bytes).unwrap();
        let world = roots[0].downcast::<World>().unwrap();
        let rgb = render_roots(&roots, 0, 16, 16, false, RenderTarget::Graphics).unwrap();
        let mid = (8 * 16 + 8) * 3;
        assert_eq!(
            rgb[mid..mid + 3],
            [255, 0, 0],
            "the lit square in the middle"
        );
        assert_eq!(world.animate(0).unwrap(), i32::MAX);
        assert_eq!(world.find(42).map(|o| o.class_name()), Some("Mesh"));
        let camera = world.active_camera().unwrap();
        let hit = world.pick(-1, 0.5, 0.5, &camera).unwrap();
        assert_eq!(
            hit.and_then(|h| h.intersected()).map(|n| n.user_id()),
            Some(42)
        );
        let copy = world.duplicate();
        assert_eq!(copy.find(42).map(|o| o.class_name()), Some("Mesh"));
        let again = writer::save(&[copy.as_object3d()], true).unwrap();
        // Debug summarizes children instead of descending 100 000 levels.
        let shown = format!("{copy:?} {roots:?}");
        assert!(
            shown.starts_with("World { user_id: 0, children: 2,"),
            "{shown}"
        );
        drop((copy, world, roots));
        let roots = Loader::load(&again).unwrap();
        assert_eq!(roots.len(), 1);
    });
}

// ---------------------------------------------------------------------------------------
// Hand-made files.

#[path = "common/corpus.rs"]
mod corpus;
#[path = "common/deep.rs"]
mod deep;
use deep::{deep_world, on_small_stack};
#[path = "common/m3g_file.rs"]
mod m3g_file;
use m3g_file::{file, mutable_image, object};

fn empty_group() -> Vec<u8> {
    let mut v = vec![0; 12]; // Object3D: user ID, no tracks, no parameters
    v.extend([0, 0]); // no transforms
    v.extend([1, 1, 255, 0xFF, 0xFF, 0xFF, 0xFF, 0]); // node defaults
    v.extend(0u32.to_le_bytes()); // no children
    object(9, &v)
}

/// A file of external references to `uris`, in order.
fn references(uris: &[&str]) -> Vec<u8> {
    let refs = uris
        .iter()
        .map(|u| object(255, format!("{u}\0").as_bytes()))
        .collect();
    file(true, &[(0, refs)])
}

fn is_budget_error(e: &Error) -> bool {
    matches!(e, Error::Io(_)) && e.to_string().contains("memory budget")
}

/// The class a load error names.
fn class_of(e: &Error) -> Option<&'static str> {
    match e {
        Error::Io(LoadError { class, .. }) => *class,
        _ => None,
    }
}

/// Runs `f` on its own thread and fails if it takes longer than 60 s (a hang).
fn within_a_minute<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(Duration::from_secs(60))
        .expect("finished within a minute (no hang)")
}

// ---------------------------------------------------------------------------------------
// Item 6: the memory budget.

/// Five mutable 4096² RGBA images (320 MiB) in a 250-byte file: over the default budget,
/// refused before the images are allocated; one of them (64 MiB) loads.
#[test]
fn mutable_images_past_the_budget_are_refused() {
    let five = file(false, &[(0, vec![mutable_image(4096); 5])]);
    assert!(five.len() < 300);
    let e = Loader::load(&five).unwrap_err();
    assert!(is_budget_error(&e), "{e}");
    assert_eq!(class_of(&e), Some("Image2D"), "{e}");
    let one = file(false, &[(0, vec![mutable_image(4096)])]);
    assert_eq!(Loader::load(&one).unwrap().len(), 1);
    // A smaller budget of the caller's.
    let e = Loader::new()
        .with_max_memory(1 << 20)
        .load_bytes(&file(false, &[(0, vec![mutable_image(1024)])]))
        .unwrap_err();
    assert!(is_budget_error(&e), "{e}");
}

/// A zlib section that would inflate past the budget is refused before inflating: the
/// error is the budget's, not the one its (invalid) content would give.
#[test]
fn a_zlib_section_past_the_budget_is_refused_before_inflating() {
    // 16 MiB of zeros: object type 0 (a second header) if it were ever parsed.
    let zeros = vec![0u8; 16 << 20];
    let bomb = file(false, &[(1, vec![zeros])]);
    assert!(bomb.len() < 100 << 10, "{}", bomb.len());
    let e = Loader::new()
        .with_max_memory(8 << 20)
        .load_bytes(&bomb)
        .unwrap_err();
    assert!(is_budget_error(&e), "{e}");
    let e = Loader::load(&bomb).unwrap_err();
    assert!(e.to_string().contains("second header"), "{e}");
}

/// A PNG whose header promises 8192² 16-bit RGBA (512 MiB decoded) is refused from its
/// header, before the decoder runs (it would report the missing image data instead).
#[test]
fn a_png_is_checked_against_the_budget_from_its_header() {
    let mut png = vec![0x89, b'P', b'N', b'G', 0x0D, 0x0A, 0x1A, 0x0A];
    png.extend(13u32.to_be_bytes());
    png.extend(b"IHDR");
    png.extend(8192u32.to_be_bytes());
    png.extend(8192u32.to_be_bytes());
    png.extend([16, 6, 0, 0, 0]);
    png.extend([0; 4]); // CRC (never reached)
    let e = Loader::load(&png).unwrap_err();
    assert!(is_budget_error(&e), "{e}");
}

/// A grey 4096² PNG (16 MiB decoded) referenced eight times is decoded once per load: it
/// fits a 40 MiB budget, and every reference gets the same Image2D.
#[test]
fn a_png_referenced_eight_times_is_loaded_once() {
    let d = tmp("png8");
    let mut png = Vec::new();
    image::GrayImage::new(4096, 4096)
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    std::fs::write(d.join("big.png"), png).unwrap();
    std::fs::write(d.join("eight.m3g"), references(&["big.png"; 8])).unwrap();
    let l = Loader::new()
        .with_max_memory(40 << 20)
        .load_file(d.join("eight.m3g"))
        .unwrap();
    assert_eq!(l.objects.len(), 8);
    assert!(l.objects.iter().all(|o| *o == l.objects[0]));
    assert!(l.objects[0].downcast::<Image2D>().is_some());
    // Each load counts afresh: the same loader loads the file again.
    let mut loader = Loader::new().with_max_memory(40 << 20);
    loader.load_file(d.join("eight.m3g")).unwrap();
    loader.load_file(d.join("eight.m3g")).unwrap();
    let _ = std::fs::remove_dir_all(&d);
}

// ---------------------------------------------------------------------------------------
// Item 7: external references.

/// 15 files, each referring to the next six times: 6^14 loads if every reference
/// re-loaded its file, 15 when each file is loaded once per load.
#[test]
fn a_fan_of_references_loads_each_file_once() {
    let d = tmp("fan");
    for i in 0..15 {
        let bytes = if i == 14 {
            file(false, &[(0, vec![empty_group()])])
        } else {
            references(&[format!("f{}.m3g", i + 1).as_str(); 6])
        };
        std::fs::write(d.join(format!("f{i}.m3g")), bytes).unwrap();
    }
    let top = d.join("f0.m3g");
    let l = within_a_minute(move || {
        Loader::new()
            .load_file(top)
            .map(|l| (l.objects.len(), l.objects[0].class_name()))
    })
    .unwrap();
    assert_eq!(l, (6, "Group"));
    // The same through an in-memory file system.
    let mut fs = MemoryFileSystem::new();
    for i in 0..15 {
        fs.insert(
            format!("/m/f{i}.m3g"),
            std::fs::read(d.join(format!("f{i}.m3g"))).unwrap(),
        );
    }
    let n = within_a_minute(move || {
        Loader::new()
            .with_file_system(fs)
            .load_file("/m/f0.m3g")
            .map(|l| l.objects.len())
    });
    assert_eq!(n, Ok(6));
    let _ = std::fs::remove_dir_all(&d);
}

/// A reference to a FIFO (no writer) is an error at once, as is loading a FIFO itself.
#[cfg(unix)]
#[test]
fn a_reference_to_a_fifo_does_not_block() {
    let d = tmp("fifo");
    let pipe = d.join("pipe.m3g");
    let c = std::ffi::CString::new(pipe.to_str().unwrap()).unwrap();
    // SAFETY: `c` is a NUL-terminated path that outlives the call.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o600) }, 0);
    std::fs::write(d.join("top.m3g"), references(&["pipe.m3g"])).unwrap();
    let top = d.join("top.m3g");
    let (e1, e2) = within_a_minute(move || {
        (
            Loader::load_path(top).unwrap_err(),
            Loader::load_path(pipe).unwrap_err(),
        )
    });
    assert!(e1.to_string().contains("not a regular file"), "{e1}");
    assert!(e2.to_string().contains("not a regular file"), "{e2}");
    let _ = std::fs::remove_dir_all(&d);
}

/// Devices, absolute URIs and `..` paths: refused as outside the folder; when the caller
/// allows outside references, still refused as not regular files, never read.
#[cfg(unix)]
#[test]
fn references_to_devices_and_outside_the_folder_are_refused() {
    let d = tmp("devices");
    std::os::unix::fs::symlink("/dev/zero", d.join("link.m3g")).unwrap();
    let depth = d.components().count();
    let up = format!("{}dev/zero", "../".repeat(depth));
    for uri in [
        "file:///dev/zero",
        "file:///dev/urandom",
        up.as_str(),
        "link.m3g",
    ] {
        std::fs::write(d.join("top.m3g"), references(&[uri])).unwrap();
        let top = d.join("top.m3g");
        let t2 = top.clone();
        let (strict, allowed) = within_a_minute(move || {
            (
                Loader::load_path(top).unwrap_err(),
                Loader::new()
                    .allow_outside_references(true)
                    .load_file(t2)
                    .unwrap_err(),
            )
        });
        assert!(
            strict.to_string().contains("outside the folder"),
            "{uri}: {strict}"
        );
        assert!(
            allowed.to_string().contains("not a regular file"),
            "{uri}: {allowed}"
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// `../` out of the referencing file's folder is refused unless allowed; a subfolder is
/// inside.
#[test]
fn references_stay_inside_the_referencing_files_folder() {
    let d = tmp("outside");
    std::fs::create_dir_all(d.join("sub")).unwrap();
    std::fs::write(d.join("g.m3g"), file(false, &[(0, vec![empty_group()])])).unwrap();
    std::fs::write(
        d.join("sub/g.m3g"),
        file(false, &[(0, vec![empty_group()])]),
    )
    .unwrap();
    std::fs::write(d.join("sub/up.m3g"), references(&["../g.m3g"])).unwrap();
    std::fs::write(d.join("down.m3g"), references(&["sub/g.m3g"])).unwrap();
    let e = Loader::load_path(d.join("sub/up.m3g")).unwrap_err();
    assert!(e.to_string().contains("outside the folder"), "{e}");
    assert_eq!(class_of(&e), Some("ExternalReference"));
    let ok = Loader::new()
        .allow_outside_references(true)
        .load_file(d.join("sub/up.m3g"))
        .unwrap();
    assert_eq!(ok.objects[0].class_name(), "Group");
    assert_eq!(Loader::load_path(d.join("down.m3g")).unwrap().len(), 1);
    let _ = std::fs::remove_dir_all(&d);
}

/// a → b → a: an error naming the loop, not a recursion.
#[test]
fn a_reference_cycle_is_an_error() {
    let d = tmp("cycle");
    std::fs::write(d.join("a.m3g"), references(&["b.m3g"])).unwrap();
    std::fs::write(d.join("b.m3g"), references(&["a.m3g"])).unwrap();
    let a = d.join("a.m3g");
    let e = within_a_minute(move || Loader::load_path(a).unwrap_err());
    assert!(e.to_string().contains("loop"), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

/// A referenced file longer than the budget left is refused after reading at most one
/// byte past it.
#[test]
fn a_referenced_file_is_read_within_the_budget() {
    let d = tmp("long");
    let mut big = file(false, &[(0, vec![empty_group()])]);
    big.resize(4 << 20, 0);
    std::fs::write(d.join("big.m3g"), big).unwrap();
    std::fs::write(d.join("top.m3g"), references(&["big.m3g"])).unwrap();
    let e = Loader::new()
        .with_max_memory(1 << 20)
        .load_file(d.join("top.m3g"))
        .unwrap_err();
    assert!(e.to_string().contains("memory budget"), "{e}");
    let _ = std::fs::remove_dir_all(&d);
}

/// The fuzz targets' renderer over every corpus file (Worlds through `render_roots`, root
/// nodes through `render_node`) and over the 100 000-deep chain: no panic.
#[test]
fn the_fuzz_renderer_runs_over_the_corpus_and_a_deep_chain() {
    let dir = corpus::m3g_corpus();
    let mut files = 0;
    for e in dir.iter().flat_map(std::fs::read_dir).flatten().flatten() {
        if e.path().extension().is_some_and(|x| x == "m3g") {
            let roots = Loader::load_path(e.path()).unwrap();
            fuzz_render::render_loaded(&roots);
            files += 1;
        }
    }
    assert!(dir.is_none() || files > 0, "the corpus has no .m3g file");
    on_small_stack(|| {
        let bytes = writer::save(&[deep_world().as_object3d()], false).unwrap();
        let roots = Loader::load(&bytes).unwrap();
        fuzz_render::render_loaded(&roots);
        // A root that is a node but not a World: the deep chain itself.
        let chain = roots[0].downcast::<World>().unwrap().child(0).unwrap();
        roots[0].downcast::<World>().unwrap().remove_child(&chain);
        fuzz_render::render_loaded(&[chain.as_object3d()]);
    });
}
