//! `RenderState`: everything the pipeline needs to know about how to draw, in the
//! specification's float form (ARCHITECTURE decision 1). The GL context and the M3G renderer
//! both fill one in; the pipeline never sees where it came from.

use glam::Mat4;

use super::target::{ColorMask, Rect};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    LessEqual,
    Greater,
    NotEqual,
    GreaterEqual,
    Always,
}

impl CompareFunc {
    #[inline]
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => incoming < stored,
            CompareFunc::Equal => incoming == stored,
            CompareFunc::LessEqual => incoming <= stored,
            CompareFunc::Greater => incoming > stored,
            CompareFunc::NotEqual => incoming != stored,
            CompareFunc::GreaterEqual => incoming >= stored,
            CompareFunc::Always => true,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CullFace {
    Front,
    Back,
    FrontAndBack,
}

/// Which window-space orientation counts as front-facing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Winding {
    Ccw,
    Cw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShadeModel {
    Flat,
    Smooth,
}

/// The viewport rectangle in window pixels (width and height already clamped to the maximum).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

#[derive(Clone, Debug)]
pub struct RenderState {
    pub modelview: Mat4,
    pub projection: Mat4,
    pub viewport: Viewport,
    /// `glDepthRange` near and far, each clamped to [0, 1].
    pub depth_range: [f32; 2],
    pub scissor: Option<Rect>,
    pub cull: Option<CullFace>,
    pub front_face: Winding,
    pub shade_model: ShadeModel,
    /// `Some(func)` when the depth test is enabled.
    pub depth_test: Option<CompareFunc>,
    pub depth_write: bool,
    pub color_mask: ColorMask,
}

impl RenderState {
    /// The initial state for a surface of the given size: identity matrices, a viewport and
    /// scissor box covering the surface, everything disabled, all writes enabled.
    pub fn new(width: i32, height: i32) -> RenderState {
        RenderState {
            modelview: Mat4::IDENTITY,
            projection: Mat4::IDENTITY,
            viewport: Viewport {
                x: 0,
                y: 0,
                width,
                height,
            },
            depth_range: [0.0, 1.0],
            scissor: None,
            cull: None,
            front_face: Winding::Ccw,
            shade_model: ShadeModel::Smooth,
            depth_test: None,
            depth_write: true,
            color_mask: [true; 4],
        }
    }

    /// The pixels a draw may touch in a target with `bounds`: those inside the scissor box.
    pub fn pixel_bounds(&self, b: Rect) -> Rect {
        match self.scissor {
            Some(s) => b.intersect(s),
            None => b,
        }
    }
}
