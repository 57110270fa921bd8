//! Hostile `.m3g` input (issue 19, items 5-7): scene graphs deeper than any stack, files
//! that ask for far more memory than they hold, and external references that loop, fan
//! out, or point at FIFOs and devices. Every input is generated here; each case must end
//! in `Ok` or a clear `LoadError`, never a crash, hang or runaway allocation.

use std::path::{Path, PathBuf};

use GLES_CM::m3g::loader::{render_roots, LoadError, Loader, FILE_IDENTIFIER};
use GLES_CM::m3g::*;

/// A fresh temporary folder for one test.
fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("m3g-hostile-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `f` on a thread with a 1 MiB stack: a traversal that recursed once per level of a
/// 100 000-deep chain would need far more, so recursion anywhere overflows and the test
/// process dies instead of passing.
fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap()
}

const DEPTH: usize = 100_000;

/// A World whose only child is a chain of `DEPTH` groups with a light and a red square at
/// the bottom, and a camera beside the chain looking at the square.
fn deep_world() -> World {
    let positions = VertexArray::new(4, 3, 2).unwrap();
    positions
        .set_shorts(0, 4, &[-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0])
        .unwrap();
    let normals = VertexArray::new(4, 3, 1).unwrap();
    normals
        .set_bytes(0, 4, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127])
        .unwrap();
    let vertices = VertexBuffer::new();
    vertices.set_positions(Some(&positions), 1.0, None).unwrap();
    vertices.set_normals(Some(&normals)).unwrap();
    let strip = TriangleStripArray::new_implicit(0, &[4])
        .unwrap()
        .as_index_buffer();
    let red = Material::new();
    red.set_color(Material::DIFFUSE, 0xFFFF0000u32 as i32)
        .unwrap();
    let look = Appearance::new();
    look.set_material(Some(&red));
    let mesh = Mesh::new(&vertices, &strip, Some(&look));
    mesh.set_user_id(42);

    let mut bottom = Group::new();
    bottom.add_child(&mesh).unwrap();
    bottom.add_child(&Light::new()).unwrap();
    for _ in 1..DEPTH {
        let g = Group::new();
        g.add_child(&bottom).unwrap();
        bottom = g;
    }
    let world = World::new();
    world.add_child(&bottom).unwrap();
    let camera = Camera::new();
    camera.set_perspective(60.0, 1.0, 0.1, 100.0).unwrap();
    camera.set_translation(0.0, 0.0, 3.0);
    world.add_child(&camera).unwrap();
    world.set_active_camera(&camera);
    world
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
        let rgb = render_roots(&roots, 0, 16, 16, false).unwrap();
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
        assert!(format!("{copy:?} {roots:?}").starts_with("World@"));
        drop((copy, world, roots));
        let roots = Loader::load(&again).unwrap();
        assert_eq!(roots.len(), 1);
    });
}
