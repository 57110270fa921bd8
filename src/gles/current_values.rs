//! Current vertex values other than the color (ES 1.1 §2.7), the active and client active
//! texture units, and the queries of the vertex array layouts and pointers.
#![forbid(unsafe_code)]

use super::context::{Context, MAX_TEXTURE_UNITS};
use super::get::Value;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurrentValues {
    pub normal: [f32; 3],
    /// Per texture unit.
    pub texcoord: [[f32; 4]; MAX_TEXTURE_UNITS],
}

impl Default for CurrentValues {
    fn default() -> CurrentValues {
        CurrentValues {
            normal: [0.0, 0.0, 1.0],
            texcoord: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
        }
    }
}

/// The unit `GL_TEXTUREi` names, if it exists.
pub fn texture_unit(texture: GLenum) -> Option<usize> {
    let i = texture.checked_sub(GL_TEXTURE0)? as usize;
    (i < MAX_TEXTURE_UNITS).then_some(i)
}

impl Context {
    pub fn normal(&mut self, n: [f32; 3]) {
        self.current.normal = n;
    }

    /// `glMultiTexCoord4{f,x}`: `GL_INVALID_ENUM` for a unit that does not exist.
    pub fn multi_tex_coord(&mut self, target: GLenum, st: [f32; 4]) {
        match texture_unit(target) {
            Some(u) => self.current.texcoord[u] = st,
            None => self.bad_enum("target", target),
        }
    }

    /// `glActiveTexture`: selects the unit of texture state, environments and matrices.
    pub fn active_texture(&mut self, texture: GLenum) {
        match texture_unit(texture) {
            Some(u) => self.active_texture = u,
            None => self.bad_enum("texture", texture),
        }
    }

    /// `glClientActiveTexture`: selects the unit of `glTexCoordPointer` and the texture
    /// coordinate array's client state.
    pub fn client_active_texture(&mut self, texture: GLenum) {
        match texture_unit(texture) {
            Some(u) => self.arrays.client_active_texture = u,
            None => self.bad_enum("texture", texture),
        }
    }

    /// `glGetPointerv`: the address given to the array's `gl*Pointer` call (the texture
    /// coordinate array of the client active unit).
    pub fn get_pointer(&mut self, pname: GLenum) -> Option<usize> {
        if let Some(p) = self.debug_pointer(pname) {
            return Some(p);
        }
        let a = &self.arrays;
        Some(match pname {
            GL_VERTEX_ARRAY_POINTER => a.vertex.ptr.addr(),
            GL_NORMAL_ARRAY_POINTER => a.normal.ptr.addr(),
            GL_COLOR_ARRAY_POINTER => a.color.ptr.addr(),
            GL_TEXTURE_COORD_ARRAY_POINTER => a.texcoord[a.client_active_texture].ptr.addr(),
            GL_POINT_SIZE_ARRAY_POINTER_OES => a.point_size.ptr.addr(),
            GL_MATRIX_INDEX_ARRAY_POINTER_OES => a.matrix_index.ptr.addr(),
            GL_WEIGHT_ARRAY_POINTER_OES => a.weight.ptr.addr(),
            _ => {
                self.bad_enum("pname", pname);
                return None;
            }
        })
    }

    /// Whether client array `array` is enabled, or `None` when `array` names none.
    pub(super) fn client_array_enabled(&self, array: GLenum) -> Option<bool> {
        let a = &self.arrays;
        Some(match array {
            GL_VERTEX_ARRAY => a.vertex.enabled,
            GL_NORMAL_ARRAY => a.normal.enabled,
            GL_COLOR_ARRAY => a.color.enabled,
            GL_TEXTURE_COORD_ARRAY => a.texcoord[a.client_active_texture].enabled,
            GL_POINT_SIZE_ARRAY_OES => a.point_size.enabled,
            GL_MATRIX_INDEX_ARRAY_OES => a.matrix_index.enabled,
            GL_WEIGHT_ARRAY_OES => a.weight.enabled,
            _ => return None,
        })
    }

    pub(super) fn current_values_value(&self, pname: GLenum) -> Option<Value> {
        let a = &self.arrays;
        let tc = &a.texcoord[a.client_active_texture];
        Some(match pname {
            GL_CURRENT_NORMAL => Value::norm(&self.current.normal),
            GL_CURRENT_TEXTURE_COORDS => Value::floats(&self.current.texcoord[self.active_texture]),
            GL_ACTIVE_TEXTURE => Value::int((GL_TEXTURE0 as usize + self.active_texture) as i64),
            GL_CLIENT_ACTIVE_TEXTURE => {
                Value::int((GL_TEXTURE0 as usize + a.client_active_texture) as i64)
            }
            GL_NORMAL_ARRAY_TYPE => Value::int(a.normal.ty as i64),
            GL_NORMAL_ARRAY_STRIDE => Value::int(a.normal.stride as i64),
            GL_TEXTURE_COORD_ARRAY_SIZE => Value::int(tc.size as i64),
            GL_TEXTURE_COORD_ARRAY_TYPE => Value::int(tc.ty as i64),
            GL_TEXTURE_COORD_ARRAY_STRIDE => Value::int(tc.stride as i64),
            GL_POINT_SIZE_ARRAY_TYPE_OES => Value::int(a.point_size.ty as i64),
            GL_POINT_SIZE_ARRAY_STRIDE_OES => Value::int(a.point_size.stride as i64),
            _ => return None,
        })
    }
}
