//! The rendering core: plain Rust, no FFI types. Both faces of the library, the GL/EGL state
//! machines and the M3G scene graph, describe what to draw as a [`RenderState`] plus a
//! [`DrawCall`] and hand it to [`render`], which runs
//! vertex → clip → setup → raster → fragment into a [`Target`].

pub mod bin;
pub mod clip;
pub mod fixed;
pub mod fragment;
pub mod raster;
pub mod reference;
pub mod setup;
pub mod state;
pub mod target;
pub mod vertex;

pub use bin::Frame;
pub use state::{CompareFunc, CullFace, RenderState, ShadeModel, Viewport, Winding};
pub use target::{ColorFormat, DepthFormat, Rect, Target, TargetFormat};
pub use vertex::{AttribArray, AttribSource, ComponentType, DrawCall, Indices, Primitive};

/// The subpixel precision of window coordinates: positions snap to 1/2⁸ pixel.
pub const SUBPIXEL_BITS: u32 = 8;
/// The largest viewport width and height. With [`SUBPIXEL_BITS`] it bounds every snapped
/// coordinate the rasterizer sees to 2¹⁴·2⁸ = 2²², so edge products stay far below 2⁶³.
pub const MAX_VIEWPORT_DIM: u32 = 8192;

/// The pipeline could not allocate memory for a draw call's vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OutOfMemory;

/// Transforms, clips and sets up `draw` with `state`, recording its primitives in `frame`
/// (for a target of `frame`'s size and format) for a later [`Frame::flush`].
pub fn record(
    state: &RenderState,
    draw: &DrawCall<'_>,
    frame: &mut Frame,
) -> Result<(), OutOfMemory> {
    let bounds = state.pixel_bounds(frame.bounds());
    if bounds.is_empty() {
        return Ok(());
    }
    let vertices = vertex::run(state, draw)?;
    let key = frame.key(fragment::FragmentKey::new(state, frame.format()));
    draw.primitive.for_each_triangle(&draw.indices, |a, b, c| {
        let (a, b, c) = (&vertices[a], &vertices[b], &vertices[c]);
        clip::triangle(a, b, c, |poly| {
            // The clipped polygon is convex: fan it out from its first vertex.
            for i in 1..poly.len() - 1 {
                let tri = [&poly[0], &poly[i], &poly[i + 1]];
                if let Some(t) = setup::triangle(state, tri, c, bounds) {
                    frame.triangle(t, key);
                }
            }
        });
    });
    Ok(())
}

/// Draws `draw` with `state` into `target` and returns when every pixel is written.
pub fn render(
    state: &RenderState,
    draw: &DrawCall<'_>,
    target: &mut Target,
) -> Result<(), OutOfMemory> {
    let mut frame = Frame::new(target.width(), target.height(), target.format());
    record(state, draw, &mut frame)?;
    frame.flush(target, bin::thread_count());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Mat4;

    fn target(w: u32, h: u32) -> Target {
        Target::new(
            w,
            h,
            TargetFormat {
                color: ColorFormat::Rgba8888,
                depth: Some(DepthFormat::D24),
                stencil_bits: 8,
            },
        )
    }

    /// A state whose projection maps object x, y straight to window pixels.
    fn pixel_state(w: i32, h: i32) -> RenderState {
        let mut s = RenderState::new(w, h);
        s.projection = Mat4::orthographic_rh_gl(0.0, w as f32, 0.0, h as f32, -1.0, 1.0);
        s
    }

    fn draw(state: &RenderState, t: &mut Target, xyz: &[f32], color: [f32; 4], prim: Primitive) {
        let bytes: Vec<u8> = xyz.iter().flat_map(|v| v.to_ne_bytes()).collect();
        let call = DrawCall {
            primitive: prim,
            indices: Indices::Range {
                first: 0,
                count: xyz.len() / 3,
            },
            position: AttribArray {
                data: &bytes,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
            color: AttribSource::Constant(color),
        };
        render(state, &call, t).unwrap();
    }

    fn count(t: &Target, rgba: [u8; 4]) -> usize {
        t.color()
            .iter()
            .filter(|&&w| w.to_le_bytes() == rgba)
            .count()
    }

    #[test]
    fn a_square_of_two_triangles_covers_each_pixel_once() {
        let mut t = target(16, 16);
        let s = pixel_state(16, 16);
        // Two triangles sharing the diagonal; colors add up in the red channel only if a
        // pixel is hit twice, which the depth test (EQUAL after the first write) catches.
        let quad = [
            2., 3., 0., 12., 3., 0., 12., 11., 0., 2., 3., 0., 12., 11., 0., 2., 11., 0.,
        ];
        draw(&s, &mut t, &quad, [1., 0., 0., 1.], Primitive::Triangles);
        assert_eq!(count(&t, [255, 0, 0, 255]), 10 * 8);
        for y in 3..11 {
            for x in 2..12 {
                assert_eq!(t.pixel(x, y), [255, 0, 0, 255], "({x},{y})");
            }
        }
    }

    #[test]
    fn shared_edges_are_drawn_exactly_once() {
        // A fan with arbitrary, non-integer vertices; every pixel is counted by its triangle.
        let mut hits = vec![0u32; 32 * 32];
        let center = [15.3f32, 16.7];
        let ring: Vec<[f32; 2]> = (0..=12)
            .map(|i| {
                let a = i as f32 / 12.0 * std::f32::consts::TAU;
                [center[0] + 13.1 * a.cos(), center[1] + 12.7 * a.sin()]
            })
            .collect();
        let s = pixel_state(32, 32);
        for i in 0..12 {
            let mut t = target(32, 32);
            let tri = [
                center[0],
                center[1],
                0.,
                ring[i][0],
                ring[i][1],
                0.,
                ring[i + 1][0],
                ring[i + 1][1],
                0.,
            ];
            draw(&s, &mut t, &tri, [1., 1., 1., 1.], Primitive::Triangles);
            for (h, w) in hits.iter_mut().zip(t.color()) {
                *h += u32::from(w.to_le_bytes()[0] == 255);
            }
        }
        assert!(hits.iter().all(|&h| h <= 1), "a pixel was drawn twice");
        // The fan's interior is covered without gaps.
        for y in 10..22 {
            for x in 10..22 {
                assert_eq!(hits[y * 32 + x], 1, "gap at ({x},{y})");
            }
        }
    }

    #[test]
    fn depth_test_keeps_the_nearer_triangle_in_either_order() {
        let s = {
            let mut s = pixel_state(8, 8);
            s.depth_test = Some(CompareFunc::Less);
            s
        };
        let tri = |z: f32| [0., 0., z, 8., 0., z, 0., 8., z];
        for order in [[0.5f32, -0.5], [-0.5, 0.5]] {
            let mut t = target(8, 8);
            for z in order {
                let color = if z < 0.0 {
                    [0., 1., 0., 1.]
                } else {
                    [0., 0., 1., 1.]
                };
                // Ortho maps object z to window depth 0.5 - z/2... nearer is larger z here.
                draw(&s, &mut t, &tri(z), color, Primitive::Triangles);
            }
            // glOrtho(near=-1, far=1) looks down -z: window depth = (1 - z) / 2 for z in
            // object space, so z = 0.5 is nearer (depth 0.25) than z = -0.5 (0.75).
            assert_eq!(t.pixel(1, 1), [0, 0, 255, 255]);
        }
    }

    #[test]
    fn triangles_behind_the_eye_leave_no_garbage() {
        let mut t = target(8, 8);
        let mut s = RenderState::new(8, 8);
        s.projection = Mat4::perspective_rh_gl(1.0, 1.0, 0.1, 10.0);
        let tri = [0., 0., 1., 1., 0., 1., 0., 1., -1.];
        draw(&s, &mut t, &tri, [1., 1., 1., 1.], Primitive::Triangles);
        let z = [0., 0., 0., 0., 0., 0., 0., 0., 0.];
        draw(&s, &mut t, &z, [1., 1., 1., 1.], Primitive::Triangles);
        assert_eq!(
            count(&t, [0, 0, 0, 0]),
            64,
            "nothing in front of the eye was drawn"
        );
    }

    /// A small deterministic generator so the scene is the same on every run.
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> f32 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 40) as f32 / (1u64 << 24) as f32
        }
    }

    #[test]
    fn fast_path_matches_the_reference_on_random_perspective_triangles() {
        let mut rng = Lcg(7);
        let mut s = RenderState::new(96, 64);
        s.projection = Mat4::perspective_rh_gl(1.2, 1.5, 0.5, 20.0);
        s.depth_test = Some(CompareFunc::LessEqual);
        let mut fast = target(96, 64);
        let mut slow = target(96, 64);
        for _ in 0..60 {
            let mut pos = Vec::new();
            let mut col = Vec::new();
            for _ in 0..3 {
                pos.extend([
                    rng.next() * 8.0 - 4.0,
                    rng.next() * 6.0 - 3.0,
                    -1.0 - rng.next() * 10.0,
                ]);
                col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
            }
            let pb: Vec<u8> = pos.iter().flat_map(|v| v.to_ne_bytes()).collect();
            let cb: Vec<u8> = col.iter().flat_map(|v| v.to_ne_bytes()).collect();
            let call = DrawCall {
                primitive: Primitive::Triangles,
                indices: Indices::Range { first: 0, count: 3 },
                position: AttribArray {
                    data: &pb,
                    ty: ComponentType::Float,
                    size: 3,
                    stride: 12,
                    normalized: false,
                },
                color: AttribSource::Array(AttribArray {
                    data: &cb,
                    ty: ComponentType::Float,
                    size: 4,
                    stride: 16,
                    normalized: false,
                }),
            };
            render(&s, &call, &mut fast).unwrap();
            reference::render(&s, &call, &mut slow);
        }
        let e = reference::compare(&fast, &slow);
        // Snapping to 1/256 pixel moves edges by at most 1/512 pixel, so only pixels whose
        // centers lie that close to an edge may change coverage; colors differ by f32
        // rounding (at most one step). Those bounds give the tolerances.
        eprintln!("fast vs reference: {e:?}");
        assert!(e.over_one < 0.01, "{e:?}");
        assert!(e.mean < 0.5, "{e:?}");
        assert!(e.psnr > 35.0, "{e:?}");
    }

    #[test]
    fn pixels_do_not_depend_on_the_thread_count() {
        let mut rng = Lcg(99);
        let mut s = RenderState::new(80, 70);
        s.projection = Mat4::orthographic_rh_gl(0.0, 80.0, 0.0, 70.0, -1.0, 1.0);
        s.depth_test = Some(CompareFunc::Less);
        let mut pos = Vec::new();
        let mut col = Vec::new();
        for _ in 0..300 {
            pos.extend([
                rng.next() * 90.0 - 5.0,
                rng.next() * 80.0 - 5.0,
                rng.next() * 2.0 - 1.0,
            ]);
            col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
        }
        let pb: Vec<u8> = pos.iter().flat_map(|v| v.to_ne_bytes()).collect();
        let cb: Vec<u8> = col.iter().flat_map(|v| v.to_ne_bytes()).collect();
        let call = DrawCall {
            primitive: Primitive::Triangles,
            indices: Indices::Range {
                first: 0,
                count: 300,
            },
            position: AttribArray {
                data: &pb,
                ty: ComponentType::Float,
                size: 3,
                stride: 12,
                normalized: false,
            },
            color: AttribSource::Array(AttribArray {
                data: &cb,
                ty: ComponentType::Float,
                size: 4,
                stride: 16,
                normalized: false,
            }),
        };
        let images: Vec<Target> = [1, 2, 3, 8]
            .iter()
            .map(|&threads| {
                let mut t = target(80, 70);
                let mut frame = Frame::new(80, 70, t.format());
                frame.clear_color(t.bounds(), 0x11223344, 0);
                record(&s, &call, &mut frame).unwrap();
                frame.flush(&mut t, threads);
                t
            })
            .collect();
        for t in &images[1..] {
            assert_eq!(t.color(), images[0].color());
            assert_eq!(t.depth(), images[0].depth());
        }
        assert!(
            images[0].color().iter().any(|&w| w != 0x11223344),
            "something was drawn"
        );
    }
}
