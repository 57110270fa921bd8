//! The benchmark's scenes. Each is one description (vertex data, matrices, enables, draws)
//! from which both the GL call sequence and the core `RenderState` + `DrawCall` pairs for
//! the reference renderer are generated, so the two can never drift apart.

use glam::{Mat4, Vec4};
use gles_cm_core::state::{Blend, BlendFactor};
use gles_cm_core::{
    AttribArray, AttribSource, ColorFormat, CompareFunc, ComponentType, DepthFormat, DrawCall,
    Indices, Primitive, RenderState, Target, TargetFormat,
};

pub const WIDTH: u32 = 640;
pub const HEIGHT: u32 = 480;

/// The scene names, in table order.
pub const NAMES: [&str; 3] = ["triangles", "blend", "lines"];

/// A fixed pseudo-random sequence, so every process builds the same scene.
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

/// One `glDrawArrays` over a range of the scene's arrays.
pub struct Draw {
    pub primitive: Primitive,
    pub first: usize,
    pub count: usize,
    /// `glPointSize` for this draw.
    pub point_size: f32,
}

/// What the throughput column counts for a scene.
#[derive(Clone, Copy)]
pub enum Work {
    /// Triangles per frame, shown as Mtris/s.
    Triangles(f64),
    /// Pixels written per frame, shown as Mpix/s.
    Pixels(f64),
    /// Lines and points per frame, shown as Mprims/s.
    Primitives(f64),
}

impl Work {
    /// The throughput of one frame taking `seconds`, with its unit.
    pub fn throughput(self, seconds: f64) -> String {
        match self {
            Work::Triangles(n) => format!("{:.2} Mtris/s", n / seconds / 1e6),
            Work::Pixels(n) => format!("{:.0} Mpix/s", n / seconds / 1e6),
            Work::Primitives(n) => format!("{:.2} Mprims/s", n / seconds / 1e6),
        }
    }
}

pub struct Scene {
    /// One line for the table's header: what is drawn and how many pixels it touches.
    pub summary: String,
    pub work: Work,
    pub projection: Mat4,
    pub modelview: Mat4,
    pub depth_test: bool,
    pub blend: bool,
    pub clear_color: [f32; 4],
    /// x, y, z per vertex.
    pub positions: Vec<f32>,
    /// r, g, b, a per vertex.
    pub colors: Vec<f32>,
    pub draws: Vec<Draw>,
}

fn bytes(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_ne_bytes()).collect()
}

impl Scene {
    pub fn by_name(name: &str) -> Option<Scene> {
        match name {
            "triangles" => Some(Scene::triangles()),
            "blend" => Some(Scene::blend()),
            "lines" => Some(Scene::lines()),
            _ => None,
        }
    }

    /// 20 000 random smooth-colored, depth-tested triangles in perspective.
    fn triangles() -> Scene {
        const N: usize = 20_000;
        let mut rng = Lcg(2026);
        let projection = Mat4::perspective_rh_gl(1.0, WIDTH as f32 / HEIGHT as f32, 0.5, 50.0);
        let (mut pos, mut col) = (Vec::new(), Vec::new());
        for _ in 0..N {
            let center = [
                rng.next() * 16.0 - 8.0,
                rng.next() * 12.0 - 6.0,
                -2.0 - rng.next() * 20.0,
            ];
            for _ in 0..3 {
                pos.extend([
                    center[0] + rng.next() * 2.0 - 1.0,
                    center[1] + rng.next() * 2.0 - 1.0,
                    center[2] + rng.next() - 0.5,
                ]);
                col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
            }
        }
        let area = projected_area(&projection, &pos);
        Scene {
            summary: format!(
                "{N} smooth depth-tested triangles in perspective; {:.2} Mpix of triangle area \
                 inside the viewport per frame (before the depth test)",
                area / 1e6
            ),
            work: Work::Triangles(N as f64),
            projection,
            modelview: Mat4::IDENTITY,
            depth_test: true,
            blend: false,
            clear_color: [0.125, 0.0625, 0.0625, 1.0],
            positions: pos,
            colors: col,
            draws: vec![Draw {
                primitive: Primitive::Triangles,
                first: 0,
                count: N * 3,
                point_size: 1.0,
            }],
        }
    }

    /// 200 large axis-aligned quads on whole-pixel corners, alpha-blended, no depth: the
    /// blended pixel count is exact.
    fn blend() -> Scene {
        const N: usize = 200;
        let mut rng = Lcg(7001);
        let (mut pos, mut col) = (Vec::new(), Vec::new());
        let mut pixels = 0.0;
        for _ in 0..N {
            let w = (160.0 + rng.next() * 240.0).floor();
            let h = (120.0 + rng.next() * 180.0).floor();
            let x0 = (rng.next() * (WIDTH as f32 - w)).floor();
            let y0 = (rng.next() * (HEIGHT as f32 - h)).floor();
            let (x1, y1) = (x0 + w, y0 + h);
            pixels += f64::from(w * h);
            let z = 0.0;
            let corners = [[x0, y0], [x1, y0], [x1, y1], [x0, y0], [x1, y1], [x0, y1]];
            let quad_colors: Vec<[f32; 4]> = (0..4)
                .map(|_| [rng.next(), rng.next(), rng.next(), 0.2 + rng.next() * 0.6])
                .collect();
            for (i, c) in corners.iter().enumerate() {
                pos.extend([c[0], c[1], z]);
                let k = [0, 1, 2, 0, 2, 3][i];
                col.extend(quad_colors[k]);
            }
        }
        Scene {
            summary: format!(
                "{N} smooth-colored quads (2 triangles each) with SRC_ALPHA, ONE_MINUS_SRC_ALPHA \
                 blending, no depth; {:.2} Mpix blended per frame ({:.0} screens)",
                pixels / 1e6,
                pixels / f64::from(WIDTH * HEIGHT)
            ),
            work: Work::Pixels(pixels),
            projection: pixel_ortho(),
            modelview: Mat4::IDENTITY,
            depth_test: false,
            blend: true,
            clear_color: [0.0, 0.0, 0.0, 1.0],
            positions: pos,
            colors: col,
            draws: vec![Draw {
                primitive: Primitive::Triangles,
                first: 0,
                count: N * 6,
                point_size: 1.0,
            }],
        }
    }

    /// 20 000 random aliased lines, then 5 000 size-4 points, depth-tested.
    fn lines() -> Scene {
        const LINES: usize = 20_000;
        const POINTS: usize = 5_000;
        let mut rng = Lcg(4242);
        let (mut pos, mut col) = (Vec::new(), Vec::new());
        let mut fragments = 0.0;
        for _ in 0..LINES {
            let x = rng.next() * (WIDTH as f32 + 40.0) - 20.0;
            let y = rng.next() * (HEIGHT as f32 + 40.0) - 20.0;
            let len = 4.0 + rng.next() * 60.0;
            let angle = rng.next() * std::f32::consts::TAU;
            let (dx, dy) = (len * angle.cos(), len * angle.sin());
            fragments += f64::from(dx.abs().max(dy.abs()));
            for p in [[x, y], [x + dx, y + dy]] {
                pos.extend([p[0], p[1], rng.next() * 1.8 - 0.9]);
                col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
            }
        }
        for _ in 0..POINTS {
            pos.extend([
                rng.next() * WIDTH as f32,
                rng.next() * HEIGHT as f32,
                rng.next() * 1.8 - 0.9,
            ]);
            col.extend([rng.next(), rng.next(), rng.next(), 1.0]);
        }
        fragments += (POINTS * 16) as f64;
        Scene {
            summary: format!(
                "{LINES} aliased width-1 lines (4-64 px long) + {POINTS} size-4 points, \
                 depth-tested; about {:.2} Mpix of fragments per frame",
                fragments / 1e6
            ),
            work: Work::Primitives((LINES + POINTS) as f64),
            projection: pixel_ortho(),
            modelview: Mat4::IDENTITY,
            depth_test: true,
            blend: false,
            clear_color: [0.05, 0.05, 0.1, 1.0],
            positions: pos,
            colors: col,
            draws: vec![
                Draw {
                    primitive: Primitive::Lines,
                    first: 0,
                    count: LINES * 2,
                    point_size: 1.0,
                },
                Draw {
                    primitive: Primitive::Points,
                    first: LINES * 2,
                    count: POINTS,
                    point_size: 4.0,
                },
            ],
        }
    }

    /// The core state for one of the scene's draws: what the GL calls of
    /// `child::draw_frame` set up.
    pub fn render_state(&self, draw: &Draw) -> RenderState {
        let mut s = RenderState::new(WIDTH as i32, HEIGHT as i32);
        s.projection = self.projection;
        s.modelview = self.modelview;
        s.depth_test = self.depth_test.then_some(CompareFunc::Less);
        s.blend = self
            .blend
            .then(|| Blend::func(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha));
        s.dither = false;
        s.point_size = draw.point_size;
        s.line_width = 1.0;
        s
    }

    /// The reference image: the cleared target, then every draw through the f64 renderer.
    pub fn reference(&self) -> Target {
        let mut t = target();
        t.clear_color(t.bounds(), self.clear_color, [true; 4]);
        t.clear_depth(t.bounds(), 1.0);
        let (pos, col) = (bytes(&self.positions), bytes(&self.colors));
        for d in &self.draws {
            let call = DrawCall {
                color: AttribSource::Array(AttribArray {
                    data: &col,
                    ty: ComponentType::Float,
                    size: 4,
                    stride: 16,
                    normalized: false,
                }),
                ..DrawCall::new(
                    d.primitive,
                    Indices::Range {
                        first: d.first,
                        count: d.count,
                    },
                    AttribArray {
                        data: &pos,
                        ty: ComponentType::Float,
                        size: 3,
                        stride: 12,
                        normalized: false,
                    },
                )
            };
            gles_cm_core::reference::render(&self.render_state(d), &call, &mut t);
        }
        t
    }
}

/// An empty 640×480 RGBA8888 / D24 target: the pbuffer's format.
pub fn target() -> Target {
    Target::new(
        WIDTH,
        HEIGHT,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D24),
            stencil_bits: 0,
        },
    )
}

/// Object x, y straight to window pixels, z in [-1, 1] to depth.
fn pixel_ortho() -> Mat4 {
    Mat4::orthographic_rh_gl(0.0, WIDTH as f32, 0.0, HEIGHT as f32, -1.0, 1.0)
}

/// The summed window-space area of the triangles in `pos`, each clipped to the viewport
/// (every vertex must be in front of the eye, as in the triangles scene).
fn projected_area(projection: &Mat4, pos: &[f32]) -> f64 {
    let to_window = |p: &[f32]| {
        let c = *projection * Vec4::new(p[0], p[1], p[2], 1.0);
        let (x, y) = (c.x / c.w, c.y / c.w);
        [
            (f64::from(x) + 1.0) * 0.5 * f64::from(WIDTH),
            (f64::from(y) + 1.0) * 0.5 * f64::from(HEIGHT),
        ]
    };
    let mut total = 0.0;
    for tri in pos.chunks(9) {
        let mut poly: Vec<[f64; 2]> = tri.chunks(3).map(to_window).collect();
        // Sutherland-Hodgman against the four sides of the viewport.
        let planes: [(usize, f64, f64); 4] = [
            (0, 0.0, 1.0),
            (0, f64::from(WIDTH), -1.0),
            (1, 0.0, 1.0),
            (1, f64::from(HEIGHT), -1.0),
        ];
        for (axis, edge, sign) in planes {
            let inside = |p: &[f64; 2]| (p[axis] - edge) * sign;
            let mut out = Vec::new();
            for i in 0..poly.len() {
                let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
                let (da, db) = (inside(&a), inside(&b));
                if da >= 0.0 {
                    out.push(a);
                }
                if (da >= 0.0) != (db >= 0.0) {
                    let t = da / (da - db);
                    out.push([a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]);
                }
            }
            poly = out;
            if poly.len() < 3 {
                break;
            }
        }
        let mut twice = 0.0;
        for i in 0..poly.len() {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            twice += a[0] * b[1] - b[0] * a[1];
        }
        total += twice.abs() * 0.5;
    }
    total
}
