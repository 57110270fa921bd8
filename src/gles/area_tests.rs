//! Tests of the fixed-function state areas (per-fragment, points and lines, clip planes,
//! lighting, fog, current values, texture environments) through the safe API.
#![forbid(unsafe_code)]

use std::sync::{Arc, Mutex};

use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};

use super::context::{Context, Surface, MAX_TEXTURE_UNITS};
use super::ffi::ClientPtr;
use super::params::{fixed_reply, Params};
use super::tokens::*;
use super::types::*;

struct Memory(Mutex<Target>);

impl Surface for Memory {
    fn target(&self) -> &Mutex<Target> {
        &self.0
    }
}

fn context() -> Context {
    let s = Arc::new(Memory(Mutex::new(Target::new(
        4,
        4,
        TargetFormat {
            color: ColorFormat::Rgba8888,
            depth: Some(DepthFormat::D16),
            stencil_bits: 8,
        },
    ))));
    let mut c = Context::new(None);
    c.make_current(Some(s.clone()), Some(s));
    c
}

fn ints(c: &mut Context, pname: u32) -> Vec<i32> {
    c.state_value(pname)
        .expect("known pname")
        .as_integers()
        .collect()
}

fn floats(c: &mut Context, pname: u32) -> Vec<f32> {
    c.state_value(pname)
        .expect("known pname")
        .as_floats()
        .collect()
}

fn fixed(c: &mut Context, pname: u32) -> Vec<i32> {
    c.state_value(pname)
        .expect("known pname")
        .as_fixed()
        .collect()
}

#[test]
fn fragment_state_defaults_errors_and_queries() {
    let mut c = context();
    assert_eq!(ints(&mut c, GL_ALPHA_TEST_FUNC), [GL_ALWAYS as i32]);
    assert_eq!(ints(&mut c, GL_BLEND_SRC), [GL_ONE as i32]);
    assert_eq!(ints(&mut c, GL_BLEND_DST), [GL_ZERO as i32]);
    assert_eq!(ints(&mut c, GL_LOGIC_OP_MODE), [GL_COPY as i32]);
    assert_eq!(ints(&mut c, GL_STENCIL_VALUE_MASK), [-1]);
    assert_eq!(floats(&mut c, GL_SAMPLE_COVERAGE_VALUE), [1.0]);

    c.alpha_func(GL_GEQUAL, 2.0);
    assert_eq!(floats(&mut c, GL_ALPHA_TEST_REF), [1.0]);
    assert_eq!(ints(&mut c, GL_ALPHA_TEST_REF), [i32::MAX]);
    c.alpha_func(GL_ONE, 0.5);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(ints(&mut c, GL_ALPHA_TEST_FUNC), [GL_GEQUAL as i32]);

    // SRC_COLOR is a destination factor only; SRC_ALPHA_SATURATE a source factor only.
    c.blend_func(GL_SRC_COLOR, GL_ZERO);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.blend_func(GL_ONE, GL_SRC_ALPHA_SATURATE);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.blend_func(GL_SRC_ALPHA_SATURATE, GL_SRC_COLOR);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(ints(&mut c, GL_BLEND_DST), [GL_SRC_COLOR as i32]);

    c.logic_op(GL_SET + 1);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.stencil_func(GL_LESS, 300, 0x0f);
    assert_eq!(ints(&mut c, GL_STENCIL_REF), [255]);
    c.stencil_op(GL_KEEP, GL_INCR, GL_ONE);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(ints(&mut c, GL_STENCIL_PASS_DEPTH_FAIL), [GL_KEEP as i32]);

    c.sample_coverage(-1.0, true);
    assert_eq!(floats(&mut c, GL_SAMPLE_COVERAGE_VALUE), [0.0]);
    c.polygon_offset(1.5, -2.0, 0.0);
    assert_eq!(fixed(&mut c, GL_POLYGON_OFFSET_FACTOR), [0x18000]);
    assert_eq!(ints(&mut c, GL_POLYGON_OFFSET_UNITS), [-2]);
}

#[test]
fn points_and_lines() {
    let mut c = context();
    assert_eq!(floats(&mut c, GL_POINT_SIZE_MAX), [64.0]);
    assert_eq!(
        floats(&mut c, GL_POINT_DISTANCE_ATTENUATION),
        [1.0, 0.0, 0.0]
    );
    c.line_width(0.0);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.point_size(-1.0);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.point_parameter(GL_POINT_SIZE_MIN, Params::Fixed(&[-1]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.point_parameter(GL_POINT_DISTANCE_ATTENUATION, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.point_parameter(GL_POINT_SIZE, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.point_parameter(GL_POINT_FADE_THRESHOLD_SIZE, Params::Fixed(&[0x28000]));
    assert_eq!(floats(&mut c, GL_POINT_FADE_THRESHOLD_SIZE), [2.5]);
    c.point_parameter(
        GL_POINT_DISTANCE_ATTENUATION,
        Params::Float(&[0.0, 1.0, 0.5]),
    );
    assert_eq!(
        floats(&mut c, GL_POINT_DISTANCE_ATTENUATION),
        [0.0, 1.0, 0.5]
    );
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn clip_planes_are_stored_in_eye_coordinates() {
    let mut c = context();
    c.translate(0.0, 0.0, -5.0);
    // z ≥ -1 in object coordinates is ze ≥ -6 in eye coordinates.
    c.clip_plane(GL_CLIP_PLANE0 + 2, [0.0, 0.0, 1.0, 1.0]);
    assert_eq!(
        c.get_clip_plane(GL_CLIP_PLANE0 + 2),
        Some([0.0, 0.0, 1.0, 6.0])
    );
    c.clip_plane(GL_CLIP_PLANE0 + 6, [0.0; 4]);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(c.get_clip_plane(GL_LIGHT0), None);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn lights_transform_and_validate() {
    let mut c = context();
    let l1 = c.get_light(GL_LIGHT1, GL_DIFFUSE).unwrap();
    assert_eq!(l1.as_floats().collect::<Vec<_>>(), [0.0, 0.0, 0.0, 1.0]);
    let l0 = c.get_light(GL_LIGHT0, GL_SPECULAR).unwrap();
    assert_eq!(fixed_reply(&l0).collect::<Vec<_>>(), [0x10000; 4]);

    c.translate(1.0, 2.0, 3.0);
    c.light(GL_LIGHT3, GL_POSITION, Params::Float(&[1.0, 1.0, 1.0, 1.0]));
    let p = c.get_light(GL_LIGHT3, GL_POSITION).unwrap();
    assert_eq!(p.as_floats().collect::<Vec<_>>(), [2.0, 3.0, 4.0, 1.0]);
    c.light(
        GL_LIGHT3,
        GL_SPOT_DIRECTION,
        Params::Float(&[0.0, 0.0, -1.0]),
    );
    let d = c.get_light(GL_LIGHT3, GL_SPOT_DIRECTION).unwrap();
    assert_eq!(d.as_floats().collect::<Vec<_>>(), [0.0, 0.0, -1.0]);

    for (pname, bad) in [
        (GL_SPOT_EXPONENT, 129.0),
        (GL_SPOT_CUTOFF, 91.0),
        (GL_SPOT_CUTOFF, -1.0),
        (GL_CONSTANT_ATTENUATION, -0.5),
        (GL_QUADRATIC_ATTENUATION, f32::NAN),
    ] {
        c.light(GL_LIGHT0, pname, Params::Float(&[bad]));
        assert_eq!(c.take_error(), GL_INVALID_VALUE, "{pname:#x} {bad}");
    }
    c.light(GL_LIGHT0, GL_SPOT_CUTOFF, Params::Float(&[180.0]));
    c.light(GL_LIGHT0, GL_AMBIENT, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.light(GL_LIGHT0 + 8, GL_SPOT_CUTOFF, Params::Float(&[10.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);

    c.material(GL_FRONT, GL_SHININESS, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.material(GL_FRONT_AND_BACK, GL_SHININESS, Params::Float(&[200.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.material(
        GL_FRONT_AND_BACK,
        GL_AMBIENT_AND_DIFFUSE,
        Params::Fixed(&[0x8000, 0, 0x10000, 0x10000]),
    );
    let a = c.get_material(GL_BACK, GL_AMBIENT).unwrap();
    assert_eq!(a.as_floats().collect::<Vec<_>>(), [0.5, 0.0, 1.0, 1.0]);
    assert!(c.get_material(GL_FRONT_AND_BACK, GL_AMBIENT).is_none());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert!(c.get_material(GL_FRONT, GL_AMBIENT_AND_DIFFUSE).is_none());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);

    // Color material: tracking starts on enable and follows glColor.
    c.color([0.25, 0.5, 0.75, 1.0]);
    c.set_capability(GL_COLOR_MATERIAL, true);
    let d = c.get_material(GL_FRONT, GL_DIFFUSE).unwrap();
    assert_eq!(d.as_floats().collect::<Vec<_>>(), [0.25, 0.5, 0.75, 1.0]);

    c.light_model(GL_LIGHT_MODEL_TWO_SIDE, Params::Fixed(&[1]));
    assert_eq!(ints(&mut c, GL_LIGHT_MODEL_TWO_SIDE), [1]);
    c.light_model(GL_LIGHT_MODEL_AMBIENT, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn fog_parameters() {
    let mut c = context();
    assert_eq!(ints(&mut c, GL_FOG_MODE), [GL_EXP as i32]);
    c.fog(GL_FOG_MODE, Params::Fixed(&[GL_LINEAR as i32]));
    assert_eq!(ints(&mut c, GL_FOG_MODE), [GL_LINEAR as i32]);
    c.fog(GL_FOG_MODE, Params::Float(&[GL_EXP2 as f32 + 0.5]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.fog(GL_FOG_DENSITY, Params::Float(&[-1.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.fog(GL_FOG_COLOR, Params::Float(&[1.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.fog(GL_FOG_COLOR, Params::Float(&[2.0, -1.0, 0.5, 1.0]));
    assert_eq!(floats(&mut c, GL_FOG_COLOR), [1.0, 0.0, 0.5, 1.0]);
    c.fog(GL_FOG_END, Params::Fixed(&[0x50000]));
    assert_eq!(fixed(&mut c, GL_FOG_END), [0x50000]);
}

#[test]
fn current_values_and_units() {
    let mut c = context();
    assert_eq!(floats(&mut c, GL_CURRENT_NORMAL), [0.0, 0.0, 1.0]);
    assert_eq!(
        floats(&mut c, GL_CURRENT_TEXTURE_COORDS),
        [0.0, 0.0, 0.0, 1.0]
    );
    c.multi_tex_coord(GL_TEXTURE1, [1.0, 2.0, 3.0, 4.0]);
    let beyond = GL_TEXTURE0 + MAX_TEXTURE_UNITS as GLenum;
    c.multi_tex_coord(beyond, [1.0, 2.0, 3.0, 4.0]);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.active_texture(GL_TEXTURE1);
    assert_eq!(
        floats(&mut c, GL_CURRENT_TEXTURE_COORDS),
        [1.0, 2.0, 3.0, 4.0]
    );
    assert_eq!(ints(&mut c, GL_ACTIVE_TEXTURE), [GL_TEXTURE1 as i32]);
    c.active_texture(beyond);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.client_active_texture(GL_TEXTURE1);
    c.array_pointer(
        super::arrays::ArrayKind::TexCoord,
        2,
        GL_SHORT,
        8,
        ClientPtr::offset(0x1000),
    );
    assert_eq!(ints(&mut c, GL_TEXTURE_COORD_ARRAY_SIZE), [2]);
    assert_eq!(c.get_pointer(GL_TEXTURE_COORD_ARRAY_POINTER), Some(0x1000));
    c.client_active_texture(GL_TEXTURE0);
    assert_eq!(ints(&mut c, GL_TEXTURE_COORD_ARRAY_SIZE), [4]);
    assert_eq!(c.get_pointer(GL_TEXTURE_COORD_ARRAY_POINTER), Some(0));
    c.array_pointer(
        super::arrays::ArrayKind::PointSize,
        1,
        GL_SHORT,
        0,
        ClientPtr::offset(0),
    );
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(c.get_pointer(GL_TEXTURE_COORD_ARRAY), None);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn texture_environment() {
    let mut c = context();
    let get = |c: &mut Context, t, p| {
        c.get_tex_env(t, p)
            .unwrap()
            .as_integers()
            .collect::<Vec<_>>()
    };
    assert_eq!(
        get(&mut c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE),
        [GL_MODULATE as i32]
    );
    assert_eq!(
        get(&mut c, GL_TEXTURE_ENV, GL_OPERAND2_RGB),
        [GL_SRC_ALPHA as i32]
    );
    assert_eq!(
        get(&mut c, GL_TEXTURE_ENV, GL_SRC2_ALPHA),
        [GL_CONSTANT as i32]
    );
    c.tex_env(
        GL_TEXTURE_ENV,
        GL_TEXTURE_ENV_MODE,
        Params::Fixed(&[GL_ADD as i32]),
    );
    assert_eq!(
        get(&mut c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE),
        [GL_ADD as i32]
    );
    let x = c.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE).unwrap();
    assert_eq!(fixed_reply(&x).collect::<Vec<_>>(), [GL_ADD as i32]);
    c.tex_env(GL_TEXTURE_ENV, GL_RGB_SCALE, Params::Fixed(&[0x20000]));
    let x = c.get_tex_env(GL_TEXTURE_ENV, GL_RGB_SCALE).unwrap();
    assert_eq!(fixed_reply(&x).collect::<Vec<_>>(), [0x20000]);
    c.tex_env(GL_TEXTURE_ENV, GL_ALPHA_SCALE, Params::Float(&[3.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.tex_env(
        GL_TEXTURE_ENV,
        GL_COMBINE_ALPHA,
        Params::Int(&[GL_DOT3_RGB as i32]),
    );
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.tex_env(
        GL_TEXTURE_ENV,
        GL_OPERAND1_ALPHA,
        Params::Int(&[GL_SRC_COLOR as i32]),
    );
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.tex_env(
        GL_TEXTURE_ENV,
        GL_TEXTURE_ENV_COLOR,
        Params::Int(&[i32::MAX, 0, i32::MIN, 0]),
    );
    let col = c.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR).unwrap();
    // (2c + 1) / (2³² − 1): 0 is a hair above zero, the most negative value is -1 → 0.
    let col: Vec<f32> = col.as_floats().collect();
    assert_eq!([col[0], col[2]], [1.0, 0.0]);
    assert!(col[1] > 0.0 && col[1] < 1e-9 && col[3] == col[1]);
    c.tex_env(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, Params::Int(&[2]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.tex_env(
        GL_POINT_SPRITE_OES,
        GL_TEXTURE_ENV_MODE,
        Params::Int(&[GL_ADD as i32]),
    );
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.active_texture(GL_TEXTURE1);
    c.tex_env(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, Params::Int(&[1]));
    assert_eq!(get(&mut c, GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES), [1]);
    assert_eq!(
        get(&mut c, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE),
        [GL_MODULATE as i32]
    );
    c.active_texture(GL_TEXTURE0);
    assert_eq!(get(&mut c, GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES), [0]);
    assert!(c.get_tex_env(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE).is_none());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}
