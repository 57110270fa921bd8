//! Client vertex arrays, the current vertex values, and the draw calls that read them.
#![forbid(unsafe_code)]

use gles_cm_core::{
    AttribArray, AttribSource, ComponentType, DrawCall, Indices, Primitive, RenderState,
};

use super::buffer::lock_objects;
use super::context::{Context, SharedObjects, MAX_TEXTURE_UNITS, MAX_VERTEX_UNITS};
use super::ffi::ClientPtr;
use super::objects::Binding;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// One `gl*Pointer` binding: the layout as given and the client address.
#[derive(Clone, Debug)]
pub struct ArrayPointer {
    pub size: i32,
    pub ty: GLenum,
    pub stride: i32,
    pub ptr: ClientPtr,
    pub enabled: bool,
    /// The buffer object bound to `GL_ARRAY_BUFFER` when the pointer was set (none: client
    /// memory). With one, `ptr` is a byte offset into it.
    pub buffer: Binding,
}

impl ArrayPointer {
    const fn new(size: i32) -> ArrayPointer {
        ArrayPointer {
            size,
            ty: GL_FLOAT,
            stride: 0,
            ptr: ClientPtr::offset(0),
            enabled: false,
            buffer: Binding::NONE,
        }
    }
}

#[derive(Clone, Debug)]
pub struct ClientArrays {
    pub vertex: ArrayPointer,
    pub color: ArrayPointer,
    pub normal: ArrayPointer,
    pub texcoord: [ArrayPointer; MAX_TEXTURE_UNITS],
    pub point_size: ArrayPointer,
    /// `OES_matrix_palette`.
    pub matrix_index: ArrayPointer,
    pub weight: ArrayPointer,
    pub client_active_texture: usize,
    /// The current color, used when the color array is disabled.
    pub color_value: [f32; 4],
}

impl ArrayPointer {
    /// Whether the pointer names any data: a client address or a buffer object.
    pub fn is_set(&self) -> bool {
        self.ptr.addr() != 0 || !self.buffer.is_none()
    }
}

impl ClientArrays {
    /// Runs `f` on every array pointer.
    pub fn for_each_pointer(&mut self, mut f: impl FnMut(&mut ArrayPointer)) {
        f(&mut self.vertex);
        f(&mut self.color);
        f(&mut self.normal);
        self.texcoord.iter_mut().for_each(&mut f);
        f(&mut self.point_size);
        f(&mut self.matrix_index);
        f(&mut self.weight);
    }
}

impl Default for ClientArrays {
    fn default() -> ClientArrays {
        ClientArrays {
            vertex: ArrayPointer::new(4),
            color: ArrayPointer::new(4),
            normal: ArrayPointer::new(3),
            texcoord: [const { ArrayPointer::new(4) }; MAX_TEXTURE_UNITS],
            point_size: ArrayPointer::new(1),
            matrix_index: ArrayPointer {
                ty: GL_UNSIGNED_BYTE,
                ..ArrayPointer::new(0)
            },
            weight: ArrayPointer::new(0),
            client_active_texture: 0,
            color_value: [1.0; 4],
        }
    }
}

/// Which array a `gl*Pointer` call sets, with the sizes and types it allows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArrayKind {
    Vertex,
    Color,
    Normal,
    /// The client active texture unit's texture coordinates.
    TexCoord,
    /// OES_point_size_array.
    PointSize,
    /// OES_matrix_palette.
    MatrixIndex,
    Weight,
}

fn component_type(ty: GLenum) -> Option<ComponentType> {
    Some(match ty {
        GL_BYTE => ComponentType::Byte,
        GL_UNSIGNED_BYTE => ComponentType::UnsignedByte,
        GL_SHORT => ComponentType::Short,
        GL_FIXED => ComponentType::Fixed,
        GL_FLOAT => ComponentType::Float,
        _ => return None,
    })
}

fn primitive(mode: GLenum) -> Option<Primitive> {
    Some(match mode {
        GL_POINTS => Primitive::Points,
        GL_LINES => Primitive::Lines,
        GL_LINE_LOOP => Primitive::LineLoop,
        GL_LINE_STRIP => Primitive::LineStrip,
        GL_TRIANGLES => Primitive::Triangles,
        GL_TRIANGLE_STRIP => Primitive::TriangleStrip,
        GL_TRIANGLE_FAN => Primitive::TriangleFan,
        _ => return None,
    })
}

impl Context {
    /// `glVertexPointer`, `glColorPointer`, `glNormalPointer` (size 3), `glTexCoordPointer`,
    /// `glPointSizePointerOES` (size 1): type errors are `GL_INVALID_ENUM`, size and
    /// stride errors `GL_INVALID_VALUE` (ES 1.1 §2.8).
    pub fn array_pointer(
        &mut self,
        kind: ArrayKind,
        size: i32,
        ty: GLenum,
        stride: i32,
        ptr: ClientPtr,
    ) {
        let (sizes, types): (&[i32], &[GLenum]) = match kind {
            ArrayKind::Vertex => (&[2, 3, 4], &[GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT]),
            ArrayKind::Color => (&[4], &[GL_UNSIGNED_BYTE, GL_FIXED, GL_FLOAT]),
            ArrayKind::Normal => (&[3], &[GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT]),
            ArrayKind::TexCoord => (&[2, 3, 4], &[GL_BYTE, GL_SHORT, GL_FIXED, GL_FLOAT]),
            ArrayKind::PointSize => (&[1], &[GL_FIXED, GL_FLOAT]),
            ArrayKind::MatrixIndex => (&[1, 2, 3, 4][..MAX_VERTEX_UNITS], &[GL_UNSIGNED_BYTE]),
            ArrayKind::Weight => (&[1, 2, 3, 4][..MAX_VERTEX_UNITS], &[GL_FIXED, GL_FLOAT]),
        };
        if !types.contains(&ty) {
            return self.bad_enum("type", ty);
        }
        if !sizes.contains(&size) || stride < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let a = match kind {
            ArrayKind::Vertex => &mut self.arrays.vertex,
            ArrayKind::Color => &mut self.arrays.color,
            ArrayKind::Normal => &mut self.arrays.normal,
            ArrayKind::TexCoord => &mut self.arrays.texcoord[self.arrays.client_active_texture],
            ArrayKind::PointSize => &mut self.arrays.point_size,
            ArrayKind::MatrixIndex => &mut self.arrays.matrix_index,
            ArrayKind::Weight => &mut self.arrays.weight,
        };
        a.size = size;
        a.ty = ty;
        a.stride = stride;
        a.buffer = self.buffers.array.clone();
        // With a buffer object bound the value is an offset: it must never be read as an
        // address, whatever a later binding says.
        a.ptr = if a.buffer.is_none() {
            ptr
        } else {
            ClientPtr::offset(ptr.addr())
        };
    }

    pub fn client_state(&mut self, array: GLenum, on: bool) {
        let unit = self.arrays.client_active_texture;
        let a = match array {
            GL_VERTEX_ARRAY => &mut self.arrays.vertex,
            GL_COLOR_ARRAY => &mut self.arrays.color,
            GL_NORMAL_ARRAY => &mut self.arrays.normal,
            GL_TEXTURE_COORD_ARRAY => &mut self.arrays.texcoord[unit],
            GL_POINT_SIZE_ARRAY_OES => &mut self.arrays.point_size,
            GL_MATRIX_INDEX_ARRAY_OES => &mut self.arrays.matrix_index,
            GL_WEIGHT_ARRAY_OES => &mut self.arrays.weight,
            _ => return self.bad_enum("array", array),
        };
        a.enabled = on;
    }

    pub fn color(&mut self, rgba: [f32; 4]) {
        self.arrays.color_value = rgba;
        if self.enables.color_material {
            self.lighting.track_color(rgba);
        }
    }

    pub fn draw_arrays(&mut self, mode: GLenum, first: i32, count: i32) {
        let Some(prim) = primitive(mode) else {
            return self.bad_enum("mode", mode);
        };
        if first < 0 || count < 0 {
            return self.bad_value(
                if first < 0 { "first" } else { "count" },
                first.min(count) as i64,
                "first and count must not be negative",
            );
        }
        self.draw(
            prim,
            Indices::Range {
                first: first as usize,
                count: count as usize,
            },
        );
    }

    /// `glDrawElements` with client-memory indices. The caller (the C shim) has turned the
    /// index pointer into a slice of exactly `count` elements.
    pub fn draw_elements(&mut self, mode: GLenum, indices: Indices<'_>) {
        let Some(prim) = primitive(mode) else {
            return self.bad_enum("mode", mode);
        };
        self.draw(prim, indices);
    }

    fn draw(&mut self, primitive: Primitive, indices: Indices<'_>) {
        // An incomplete framebuffer object draws nothing (and says so).
        if !self.framebuffer_ready() {
            return;
        }
        let Some((_, hi)) = indices.range() else {
            return;
        };
        // Without a vertex array nothing is drawn (ES 1.1 §2.8).
        if !self.arrays.vertex.enabled || !self.arrays.vertex.is_set() {
            return;
        }
        // Make room first: the frame must not flush while the share group is locked below.
        self.with_frame(|_, _| ());
        // Before the share group is locked: the state snapshots textures, which locks it.
        self.with_render_state(|ctx, state| ctx.record_draw(state, primitive, indices, hi));
    }

    /// Records a draw of the current arrays, whose highest index is `hi`, with `state`.
    fn record_draw(
        &mut self,
        state: &RenderState,
        primitive: Primitive,
        indices: Indices<'_>,
        hi: usize,
    ) {
        let shared = self.shared.clone();
        let objects = lock_objects(&shared);
        let position = match array_view(&objects, &self.arrays.vertex, hi, false) {
            Ok(a) => a,
            Err(e) => return self.array_error(e),
        };
        // Enabled arrays are read; disabled ones give the current value.
        let view =
            |a: &ArrayPointer, normalized: bool| -> Result<Option<AttribArray<'_>>, ArrayError> {
                if a.enabled && a.is_set() {
                    array_view(&objects, a, hi, normalized).map(Some)
                } else {
                    Ok(None)
                }
            };
        fn source(v: Option<AttribArray<'_>>, current: [f32; 4]) -> AttribSource<'_> {
            match v {
                Some(a) => AttribSource::Array(a),
                None => AttribSource::Constant(current),
            }
        }
        let a = &self.arrays;
        let n = self.current.normal;
        let palette = self.enables.matrix_palette;
        let views = (|| {
            Ok::<_, ArrayError>((
                view(&a.color, true)?,
                view(&a.normal, true)?,
                {
                    let mut t = [None; MAX_TEXTURE_UNITS];
                    for (t, a) in t.iter_mut().zip(&a.texcoord) {
                        *t = view(a, false)?;
                    }
                    t
                },
                view(&a.point_size, false)?,
                if palette {
                    view(&a.matrix_index, false)?
                } else {
                    None
                },
                if palette {
                    view(&a.weight, false)?
                } else {
                    None
                },
            ))
        })();
        let (color, normal, texcoord, point_size, matrix_index, weight) = match views {
            Ok(v) => v,
            Err(e) => return self.array_error(e),
        };
        let mut call = DrawCall::new(primitive, indices, position);
        call.color = source(color, a.color_value);
        call.normal = source(normal, [n[0], n[1], n[2], 0.0]);
        let mut texcoord = texcoord.into_iter();
        call.texcoord =
            std::array::from_fn(|u| source(texcoord.next().flatten(), self.current.texcoord[u]));
        call.point_size = point_size;
        call.matrix_index = matrix_index;
        call.weight = weight;
        let recorded =
            self.with_frame(|frame, to| gles_cm_core::record_into(state, &call, frame, to));
        if let Some(Err(_)) = recorded {
            self.set_error(GL_OUT_OF_MEMORY);
        }
    }
}

/// Why a draw cannot read an array.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArrayError {
    /// The array's extent does not fit in the address space (`GL_OUT_OF_MEMORY`).
    TooLarge,
    /// The elements lie (partly) outside their buffer object, or the buffer is gone: the
    /// draw is skipped without an error, reading nothing.
    OutOfRange,
}

impl Context {
    fn array_error(&mut self, e: ArrayError) {
        if e == ArrayError::TooLarge {
            self.set_error(GL_OUT_OF_MEMORY);
        }
    }

    /// `glDrawElements` with `GL_ELEMENT_ARRAY_BUFFER` bound: `count` indices of `size` bytes
    /// (1, 2 or 4) at byte `offset` of the buffer. Indices reaching past the buffer's end skip
    /// the draw.
    pub fn draw_elements_from_buffer(
        &mut self,
        mode: GLenum,
        count: usize,
        size: usize,
        offset: usize,
    ) {
        let Some(prim) = primitive(mode) else {
            return self.bad_enum("mode", mode);
        };
        let bytes = {
            let objects = lock_objects(&self.shared);
            let range = count.checked_mul(size).and_then(|len| {
                objects
                    .buffers
                    .get(&self.buffers.element_array)?
                    .range(offset, len)
            });
            match range {
                Some(b) => b.to_vec(),
                None => return,
            }
        };
        match size {
            1 => self.draw(prim, Indices::U8(&bytes)),
            2 => {
                let shorts: Vec<u16> = bytes
                    .chunks_exact(2)
                    .map(|b| u16::from_ne_bytes([b[0], b[1]]))
                    .collect();
                self.draw(prim, Indices::U16(&shorts));
            }
            _ => {
                let ints: Vec<u32> = bytes
                    .chunks_exact(4)
                    .map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]]))
                    .collect();
                self.draw(prim, Indices::U32(&ints));
            }
        }
    }
}

/// The memory behind `a` for elements `0..=last`: a range of its buffer object, or client
/// memory.
fn array_view<'a>(
    objects: &'a SharedObjects,
    a: &ArrayPointer,
    last: usize,
    normalized: bool,
) -> Result<AttribArray<'a>, ArrayError> {
    let ty = component_type(a.ty).ok_or(ArrayError::OutOfRange)?;
    let size = a.size as usize;
    let stride = if a.stride == 0 {
        size * ty.size()
    } else {
        a.stride as usize
    };
    let len = last
        .checked_mul(stride)
        .and_then(|l| l.checked_add(size * ty.size()))
        .ok_or(ArrayError::TooLarge)?;
    let data = if !a.buffer.is_none() {
        let buffer = objects
            .buffers
            .get(&a.buffer)
            .ok_or(ArrayError::OutOfRange)?;
        buffer
            .range(a.ptr.addr(), len)
            .ok_or(ArrayError::OutOfRange)?
    } else {
        if a.ptr.addr().checked_add(len).is_none() || len > isize::MAX as usize {
            return Err(ArrayError::TooLarge);
        }
        // `len` covers exactly the elements the draw reads: what the program vouched for.
        a.ptr.bytes(len).ok_or(ArrayError::OutOfRange)?
    };
    Ok(AttribArray {
        data,
        ty,
        size,
        stride,
        normalized,
    })
}
