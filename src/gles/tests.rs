//! Context-level tests through the safe API, with an in-memory surface (the C programs in
//! `c_tests/` cover the same ground through the ABI).
#![forbid(unsafe_code)]

use std::sync::{Arc, Mutex};

use gles_cm_core::{ColorFormat, DepthFormat, Target, TargetFormat};

use super::context::{Context, Surface};
use super::tokens::*;

struct Memory(Mutex<Target>);

impl Surface for Memory {
    fn target(&self) -> &Mutex<Target> {
        &self.0
    }
}

fn context(w: u32, h: u32, color: ColorFormat) -> (Context, Arc<Memory>) {
    let s = Arc::new(Memory(Mutex::new(Target::new(
        w,
        h,
        TargetFormat {
            color,
            depth: Some(DepthFormat::D16),
            stencil_bits: 8,
        },
    ))));
    let mut c = Context::new(None);
    c.make_current(Some(s.clone()), Some(s.clone()));
    (c, s)
}

fn int(c: &mut Context, pname: u32) -> Vec<i32> {
    c.state_value(pname)
        .expect("known pname")
        .as_integers()
        .collect()
}

#[test]
fn first_error_sticks_until_read() {
    let (mut c, _) = context(4, 4, ColorFormat::Rgba8888);
    c.set_capability(0xdead, true);
    c.viewport(0, 0, -1, 1);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn viewport_and_scissor_start_at_the_surface_size() {
    let (mut c, _) = context(7, 5, ColorFormat::Rgb565);
    assert_eq!(int(&mut c, GL_VIEWPORT), [0, 0, 7, 5]);
    assert_eq!(int(&mut c, GL_SCISSOR_BOX), [0, 0, 7, 5]);
    assert_eq!(int(&mut c, GL_RED_BITS), [5]);
    assert_eq!(int(&mut c, GL_GREEN_BITS), [6]);
    assert_eq!(int(&mut c, GL_DEPTH_BITS), [16]);
    assert_eq!(
        int(&mut c, GL_IMPLEMENTATION_COLOR_READ_TYPE_OES),
        [GL_UNSIGNED_SHORT_5_6_5 as i32]
    );
}

#[test]
fn invalid_values_leave_state_unchanged() {
    let (mut c, _) = context(8, 8, ColorFormat::Rgba8888);
    c.scissor(1, 2, 3, 4);
    c.scissor(0, 0, -1, 4);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    assert_eq!(int(&mut c, GL_SCISSOR_BOX), [1, 2, 3, 4]);
    c.pixel_store(GL_PACK_ALIGNMENT, 3);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    assert_eq!(int(&mut c, GL_PACK_ALIGNMENT), [4]);
    c.depth_func(GL_TRIANGLES);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(int(&mut c, GL_DEPTH_FUNC), [GL_LESS as i32]);
}

#[test]
fn stacks_overflow_and_underflow() {
    let (mut c, _) = context(1, 1, ColorFormat::Rgba8888);
    c.matrix_mode(GL_PROJECTION);
    c.pop_matrix();
    assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    c.push_matrix();
    c.push_matrix();
    assert_eq!(c.take_error(), GL_STACK_OVERFLOW);
    assert_eq!(int(&mut c, GL_PROJECTION_STACK_DEPTH), [2]);
}

#[test]
fn normalized_values_map_to_the_whole_integer_range() {
    let (mut c, _) = context(1, 1, ColorFormat::Rgba8888);
    c.clear_color([1.0, 0.0, 0.5, 2.0]);
    let v = int(&mut c, GL_COLOR_CLEAR_VALUE);
    assert_eq!(v[0], i32::MAX);
    assert_eq!(v[1], 0);
    assert_eq!(v[3], i32::MAX, "clear values are clamped when set");
    assert!((v[2] - (i32::MAX / 2)).abs() <= 1);
}

#[test]
fn scissored_masked_clear() {
    let (mut c, s) = context(4, 4, ColorFormat::Rgba8888);
    c.clear_color([1.0, 1.0, 1.0, 1.0]);
    c.clear(GL_COLOR_BUFFER_BIT);
    c.scissor(1, 1, 2, 2);
    c.set_capability(GL_SCISSOR_TEST, true);
    c.color_mask([false, true, true, true]);
    c.clear_color([0.0, 0.0, 0.0, 0.0]);
    c.clear(GL_COLOR_BUFFER_BIT);
    c.finish();
    let t = s.0.lock().unwrap();
    assert_eq!(t.pixel(0, 0), [255, 255, 255, 255]);
    assert_eq!(t.pixel(1, 1), [255, 0, 0, 0]);
    assert_eq!(t.pixel(2, 2), [255, 0, 0, 0]);
    assert_eq!(t.pixel(3, 3), [255, 255, 255, 255]);
    drop(t);
    c.clear(0x8000_0000);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
}

#[test]
fn read_pixels_honours_pack_alignment_and_formats() {
    let (mut c, _) = context(3, 2, ColorFormat::Rgb565);
    c.clear_color([1.0, 0.0, 1.0, 1.0]);
    c.clear(GL_COLOR_BUFFER_BIT);
    let layout = c
        .read_pixels_layout(3, 2, GL_RGB, GL_UNSIGNED_SHORT_5_6_5)
        .unwrap();
    assert_eq!((layout.row_stride, layout.len), (8, 14));
    let mut out = vec![0xAAu8; 16];
    c.read_pixels(0, 0, 3, 2, layout, &mut out);
    let px = u16::from_ne_bytes([out[8], out[9]]);
    assert_eq!(px, 0xF81F);
    assert_eq!(&out[6..8], &[0xAA, 0xAA], "padding is not written");
    assert_eq!(
        c.read_pixels_layout(1, 1, GL_RGB, GL_UNSIGNED_BYTE),
        Err(GL_INVALID_OPERATION)
    );
    assert_eq!(
        c.read_pixels_layout(1, 1, GL_DEPTH_TEST, GL_UNSIGNED_BYTE),
        Err(GL_INVALID_ENUM)
    );
    assert_eq!(
        c.read_pixels_layout(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE),
        Err(GL_INVALID_VALUE)
    );
}

#[test]
fn draw_arrays_validates_before_drawing() {
    let (mut c, _) = context(2, 2, ColorFormat::Rgba8888);
    c.draw_arrays(0x20, 0, 3);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.draw_arrays(GL_TRIANGLES, 0, -1);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    // No vertex array enabled: nothing is drawn and nothing is an error.
    c.draw_arrays(GL_TRIANGLES, 0, 3);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn version_string_has_the_specified_prefix() {
    let (mut c, _) = context(1, 1, ColorFormat::Rgba8888);
    let v = c.string(GL_VERSION).unwrap();
    assert!(v.starts_with(b"OpenGL ES-CM 1.1 "));
    assert_eq!(*v.last().unwrap(), 0);
    assert!(c.string(GL_TRUE as u32).is_none());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}
