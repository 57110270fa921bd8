//! A scene graph deeper than any stack, shared by the Loader's and the tool's hostile-input
//! tests.
#![allow(dead_code)]

use m3g::*;

/// Runs `f` on a thread with a 1 MiB stack: a traversal that recursed once per level of a
/// 100 000-deep chain would need far more, so recursion anywhere overflows and the test
/// process dies instead of passing.
pub fn on_small_stack<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(f)
        .unwrap()
        .join()
        .unwrap()
}

pub const DEPTH: usize = 100_000;

/// A World whose only child is a chain of `DEPTH` groups with a light and a red square at
/// the bottom, and a camera beside the chain looking at the square.
pub fn deep_world() -> World {
    let positions = VertexArray::new(4, 3, 2).unwrap();
    positions
        .set_shorts(0, &[-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0])
        .unwrap();
    let normals = VertexArray::new(4, 3, 1).unwrap();
    normals
        .set_bytes(0, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127])
        .unwrap();
    let vertices = VertexBuffer::new();
    vertices.set_positions(Some(&positions), 1.0, None).unwrap();
    vertices.set_normals(Some(&normals)).unwrap();
    let strip = TriangleStripArray::new_implicit(0, &[4])
        .unwrap()
        .as_index_buffer();
    let red = Material::new();
    red.set_color(MaterialColor::DIFFUSE, Color(0xFFFF0000))
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
