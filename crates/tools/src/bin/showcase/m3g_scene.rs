//! Part two of the showcase: an M3G scene built with the Rust API (a lit, textured, fogged
//! cube over a tiled floor, its orientation driven by a keyframe animation), written to a
//! .m3g file with the writer, loaded back with the Loader and rendered frame by frame
//! through `Graphics3D` into a `gles_cm_core::Target`; then a file of the corpus (or one named on
//! the command line).

use std::path::{Path, PathBuf};
use std::time::Instant;

use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};
use m3g::*;

/// Background and fog color.
const SKY: u32 = 0xFF26_3A5C;

fn checker(size: i32, a: [u8; 3], b: [u8; 3], cells: i32) -> Image2D {
    let mut px = Vec::new();
    for y in 0..size {
        for x in 0..size {
            let odd = (x * cells / size + y * cells / size) % 2 == 1;
            px.extend_from_slice(if odd { &a } else { &b });
        }
    }
    Image2D::with_pixels(ImageFormat::Rgb, size, size, &px).expect("image")
}

fn texture(image: &Image2D) -> Result<Texture2D> {
    let t = Texture2D::new(image)?;
    t.set_filtering(TextureFilter::Linear, TextureFilter::Linear)?;
    t.set_wrapping(TextureWrap::Repeat, TextureWrap::Repeat);
    t.set_blending(TextureFunction::Modulate);
    Ok(t)
}

/// A unit cube (±1) with per-face normals and texture coordinates, as six strips.
fn cube() -> Result<(VertexBuffer, IndexBuffer)> {
    // Per face: normal, then the two in-plane axes (u, v) with u × v = normal.
    let faces: [([i8; 3], [i16; 3], [i16; 3]); 6] = [
        ([0, 0, 127], [1, 0, 0], [0, 1, 0]),
        ([0, 0, -127], [-1, 0, 0], [0, 1, 0]),
        ([127, 0, 0], [0, 0, -1], [0, 1, 0]),
        ([-127, 0, 0], [0, 0, 1], [0, 1, 0]),
        ([0, 127, 0], [1, 0, 0], [0, 0, -1]),
        ([0, -127, 0], [1, 0, 0], [0, 0, 1]),
    ];
    let (mut pos, mut nrm, mut tex) = (Vec::new(), Vec::new(), Vec::new());
    for (n, u, v) in faces {
        let c: Vec<i16> = n.iter().map(|&x| (x / 127) as i16).collect();
        for (su, sv) in [(-1, -1), (1, -1), (-1, 1), (1, 1)] {
            for k in 0..3 {
                pos.push(c[k] + su * u[k] + sv * v[k]);
            }
            nrm.extend_from_slice(&n);
            tex.extend_from_slice(&[(su + 1) / 2, (1 - sv) / 2]);
        }
    }
    let positions = VertexArray::new(24, 3, 2)?;
    positions.set_shorts(0, &pos)?;
    let normals = VertexArray::new(24, 3, 1)?;
    normals.set_bytes(0, &nrm)?;
    let texcoords = VertexArray::new(24, 2, 2)?;
    texcoords.set_shorts(0, &tex)?;
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&positions), 1.0, None)?;
    vb.set_normals(Some(&normals))?;
    vb.set_tex_coords(0, Some(&texcoords), 1.0, None)?;
    let ib = TriangleStripArray::new_implicit(0, &[4; 6])?.as_index_buffer();
    Ok((vb, ib))
}

/// A square floor of side 2 · `half` at height `y`, facing up, texture repeating `reps` times.
fn floor(half: i16, y: i16, reps: i16) -> Result<(VertexBuffer, IndexBuffer)> {
    let positions = VertexArray::new(4, 3, 2)?;
    positions.set_shorts(
        0,
        &[
            -half, y, half, half, y, half, -half, y, -half, half, y, -half,
        ],
    )?;
    let normals = VertexArray::new(4, 3, 1)?;
    normals.set_bytes(0, &[0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127, 0])?;
    let texcoords = VertexArray::new(4, 2, 2)?;
    texcoords.set_shorts(0, &[0, reps, reps, reps, 0, 0, reps, 0])?;
    let vb = VertexBuffer::new();
    vb.set_positions(Some(&positions), 1.0, None)?;
    vb.set_normals(Some(&normals))?;
    vb.set_tex_coords(0, Some(&texcoords), 1.0, None)?;
    let ib = TriangleStripArray::new_implicit(0, &[4])?.as_index_buffer();
    Ok((vb, ib))
}

/// The scene: a World with a Background, a perspective Camera, a directional and an ambient
/// Light, a textured lit cube spinning through an orientation AnimationTrack (SLERP, 4 s
/// loop) and a textured floor, both fogged.
pub fn build(aspect: f32) -> Result<World> {
    let world = World::new();
    let background = Background::new();
    background.set_color(Color(SKY));
    world.set_background(Some(&background));

    let camera = Camera::new();
    camera.set_perspective(45.0, aspect, 0.5, 60.0)?;
    camera.set_translation(0.0, 2.2, 7.0);
    camera.set_orientation(-16.0, 1.0, 0.0, 0.0)?;
    world.add_child(&camera)?;
    world.set_active_camera(&camera);

    let sun = Light::new(); // directional, shining along its -Z
    sun.set_color(Color(0xFFF0E0));
    sun.set_orientation(-50.0, 1.0, 0.4, 0.0)?;
    world.add_child(&sun)?;
    let ambient = Light::new();
    ambient.set_mode(LightMode::Ambient);
    ambient.set_color(Color(0x404858));
    world.add_child(&ambient)?;

    let fog = Fog::new();
    fog.set_mode(FogMode::Linear);
    fog.set_linear(6.0, 30.0);
    fog.set_color(Color(SKY));

    let shiny = Material::new();
    shiny.set_color(MaterialColor::DIFFUSE, Color(0xFFFFFFFF))?;
    shiny.set_color(MaterialColor::AMBIENT, Color(0xFFFFFF))?;
    shiny.set_color(MaterialColor::SPECULAR, Color(0xFFFFFF))?;
    shiny.set_shininess(24.0)?;
    let cube_look = Appearance::new();
    cube_look.set_material(Some(&shiny));
    cube_look.set_fog(Some(&fog));
    cube_look.set_texture(
        0,
        Some(&texture(&checker(64, [250, 210, 80], [40, 110, 200], 4))?),
    )?;
    let (vb, ib) = cube()?;
    let cube = Mesh::new(&vb, &ib, Some(&cube_look));
    cube.set_translation(0.0, 0.3, 0.0);
    world.add_child(&cube)?;

    // Orientation keyframes: a full turn about a tilted axis, as quaternions (x, y, z, w).
    let axis = glam::Vec3::new(0.35, 1.0, 0.2).normalize();
    let spin = KeyframeSequence::new(5, 4, Interpolation::Slerp)?;
    for k in 0..5 {
        let q = glam::Quat::from_axis_angle(axis, k as f32 * std::f32::consts::FRAC_PI_2);
        spin.set_keyframe(k, k as i32 * 1000, &q.to_array())?;
    }
    spin.set_duration(4000)?;
    spin.set_repeat_mode(RepeatMode::Loop);
    let track = AnimationTrack::new(&spin, AnimationProperty::Orientation)?;
    track.set_controller(Some(&AnimationController::new()));
    cube.add_animation_track(&track)?;

    let matte = Material::new();
    let floor_look = Appearance::new();
    floor_look.set_material(Some(&matte));
    floor_look.set_fog(Some(&fog));
    floor_look.set_texture(
        0,
        Some(&texture(&checker(64, [200, 200, 190], [90, 90, 100], 2))?),
    )?;
    let (vb, ib) = floor(20, -1, 10)?;
    world.add_child(&Mesh::new(&vb, &ib, Some(&floor_look)))?;
    Ok(world)
}

/// Animates `world` to `time_ms` and renders it with its active camera into a fresh
/// `width` × `height` RGBA8888 target with a 16-bit depth buffer.
pub fn render(world: &World, time_ms: i32, width: u32, height: u32) -> Result<Target> {
    world.animate(time_ms)?;
    let format = TargetFormat {
        color: ColorFormat::Rgba8888,
        depth: Some(DepthFormat::D16),
        stencil_bits: 0,
    };
    let mut g = Graphics3D::new();
    g.bind_target(
        Target::new(width, height, format),
        true,
        RenderHints::empty(),
    )?;
    let drawn = g.render_world(world);
    let target = g.release_target().expect("the bound target");
    drawn.map(|()| target)
}

/// Saves a target (bottom row first) as an RGB PNG (top row first).
pub fn save(t: &Target, path: &Path) -> std::result::Result<(), String> {
    let mut img = image::RgbImage::new(t.width(), t.height());
    for y in 0..t.height() {
        for x in 0..t.width() {
            let [r, g, b, _] = t.pixel(x, t.height() - 1 - y);
            img.put_pixel(x, y, image::Rgb([r, g, b]));
        }
    }
    img.save(path)
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// The share of pixels of `t` (bottom row first) with some channel more than 8 steps from
/// `r` (top row first), as the corpus MANIFEST measures it.
fn off_by_more_than_8(t: &Target, r: &image::RgbImage) -> String {
    if (r.width(), r.height()) != (t.width(), t.height()) {
        return "(reference of another size)".into();
    }
    let mut off = 0;
    for (x, y, p) in r.enumerate_pixels() {
        let q = t.pixel(x, t.height() - 1 - y);
        if (0..3).any(|c| p.0[c].abs_diff(q[c]) > 8) {
            off += 1;
        }
    }
    format!(
        "{:.2} %",
        off as f64 * 100.0 / (r.width() * r.height()) as f64
    )
}

/// What part two did.
pub struct M3gRun {
    pub frames: Vec<PathBuf>,
    pub ms_per_frame: f64,
    pub lines: Vec<String>,
}

fn m3g<T>(what: &str, r: Result<T>) -> std::result::Result<T, String> {
    r.map_err(|e| format!("{what}: {e}"))
}

/// Builds the scene, writes it, loads it back, renders `times` from the loaded copy and
/// checks them against the scene as built; then renders `file` (or a corpus file).
pub fn run(out: &Path, times: &[i32], file: Option<&Path>) -> std::result::Result<M3gRun, String> {
    const W: u32 = 400;
    const H: u32 = 300;
    let mut lines = Vec::new();
    let built = m3g("building the scene", build(W as f32 / H as f32))?;
    let bytes = writer::save(&[built.as_object3d()], true).map_err(|e| e.to_string())?;
    let file_path = out.join("m3g-scene.m3g");
    std::fs::write(&file_path, &bytes).map_err(|e| format!("{}: {e}", file_path.display()))?;
    let roots = Loader::load(&bytes).map_err(|e| format!("loading it back: {e}"))?;
    let loaded = roots
        .iter()
        .find_map(|r| r.downcast::<World>())
        .ok_or("the written file has no World")?;
    lines.push(format!(
        "built with the M3G API, written with m3g::writer to {} ({} bytes, zlib), loaded back",
        file_path.display(),
        bytes.len()
    ));

    let mut frames = Vec::new();
    let mut total = 0.0;
    let (mut differing, mut worst) = (0usize, 0u8);
    for (i, &t) in times.iter().enumerate() {
        let start = Instant::now();
        let image = m3g("rendering the loaded scene", render(&loaded, t, W, H))?;
        total += start.elapsed().as_secs_f64();
        let original = m3g("rendering the built scene", render(&built, t, W, H))?;
        for (a, b) in image.color().iter().zip(original.color()) {
            if a != b {
                differing += 1;
                let step = (a.to_le_bytes().iter().zip(b.to_le_bytes()))
                    .map(|(x, y)| x.abs_diff(y))
                    .max()
                    .unwrap_or(0);
                worst = worst.max(step);
            }
        }
        let path = out.join(format!("m3g-{i:02}.png"));
        save(&image, &path)?;
        frames.push(path);
    }
    let pixels = times.len() * (W * H) as usize;
    lines.push(format!(
        "{} frames at t = {:?} ms; the loaded copy against the scene as built: {}",
        times.len(),
        times,
        if differing == 0 {
            "identical pixels".to_string()
        } else {
            format!("{differing} of {pixels} pixels differ, by at most {worst} step(s)")
        }
    ));

    // A file from outside: the one named on the command line, else one of the corpus.
    let corpus = gles_cm_tools::repo_root().join("tests/data/m3g/robot.m3g");
    let corpus = corpus.canonicalize().unwrap_or(corpus);
    let other = match file {
        Some(f) => Some(f.to_path_buf()),
        None if corpus.exists() => Some(corpus),
        None => {
            lines.push(format!(
                "no {} here: skipped loading a corpus file (name a .m3g file on the command line)",
                corpus.display()
            ));
            None
        }
    };
    if let Some(path) = other {
        let name = path
            .file_stem()
            .map_or("file".into(), |s| s.to_string_lossy().into_owned());
        let roots = Loader::load_path(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let world = roots
            .iter()
            .find_map(|r| r.downcast::<World>())
            .ok_or_else(|| format!("{}: no World among the root objects", path.display()))?;
        let mut written = Vec::new();
        let mut against = Vec::new();
        for &t in &[0, 1000, 2500] {
            let image = m3g(
                &format!("rendering {}", path.display()),
                render(&world, t, 240, 320),
            )?;
            let png = out.join(format!("m3g-{name}-t{t}.png"));
            save(&image, &png)?;
            written.push(png.file_name().unwrap().to_string_lossy().into_owned());
            // The corpus's reference images (JSR-184 reference engine, same conditions).
            let reference = path.with_file_name(format!("reference/{name}_t{t}.png"));
            if let Ok(r) = image::open(&reference) {
                against.push(format!("t{t} {}", off_by_more_than_8(&image, &r.to_rgb8())));
            }
        }
        lines.push(format!(
            "loaded {} and rendered it at t = 0, 1000, 2500 ms: {}",
            path.display(),
            written.join(", ")
        ));
        if !against.is_empty() {
            lines.push(format!(
                "against the JSR-184 reference engine's images, pixels off by more than 8 steps: {}",
                against.join(", ")
            ));
        }
    }
    Ok(M3gRun {
        frames,
        ms_per_frame: total * 1e3 / times.len() as f64,
        lines,
    })
}
