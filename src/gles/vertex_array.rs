//! `OES_vertex_array_object`: named sets of vertex array state that one bind switches.
//!
//! A vertex array object holds every array pointer with its enable flag and the buffer it
//! reads, and the `GL_ELEMENT_ARRAY_BUFFER` binding. The `GL_ARRAY_BUFFER` binding, the
//! client active texture and the current vertex values stay the context's. Objects belong
//! to the context that made them (the extension does not share them).
//!
//! The bound object's state is the context's live state (`Context::arrays`,
//! `Context::buffers.element_array`), so draws read it as before; binding another object
//! parks the live state in the previous object's slot and takes the new one's.

use super::arrays::ClientArrays;
use super::context::Context;
use super::fbo::ContextNames;
use super::get::Value;
use super::objects::Binding;
use super::tokens::*;
use super::tokens_ext::GL_VERTEX_ARRAY_BINDING_OES;
use super::types::*;

/// The state one vertex array object holds while another is bound.
#[derive(Default)]
struct Parked {
    arrays: ClientArrays,
    element_array: Binding,
}

/// A context's vertex array objects.
#[derive(Default)]
pub struct VertexArrays {
    /// The objects, made when first bound; the bound one's slot is empty (its state is live).
    names: ContextNames<Parked>,
    /// The state of object 0, the default, while another is bound.
    default: Parked,
    /// `GL_VERTEX_ARRAY_BINDING_OES`.
    bound: GLuint,
}

/// Exchanges the array pointers of `a` and `b` (not the selector or current values).
fn swap_pointers(a: &mut ClientArrays, b: &mut ClientArrays) {
    std::mem::swap(&mut a.vertex, &mut b.vertex);
    std::mem::swap(&mut a.color, &mut b.color);
    std::mem::swap(&mut a.normal, &mut b.normal);
    std::mem::swap(&mut a.texcoord, &mut b.texcoord);
    std::mem::swap(&mut a.point_size, &mut b.point_size);
    std::mem::swap(&mut a.matrix_index, &mut b.matrix_index);
    std::mem::swap(&mut a.weight, &mut b.weight);
}

impl Context {
    pub fn gen_vertex_arrays(&mut self, n: i32) -> Vec<GLuint> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return Vec::new();
        }
        (0..n)
            .map(|_| self.vertex_arrays.names.generate())
            .collect()
    }

    /// `glBindVertexArrayOES`: names not generated (or deleted) are `GL_INVALID_OPERATION`.
    pub fn bind_vertex_array(&mut self, name: GLuint) {
        if name != 0 && !self.vertex_arrays.names.contains(name) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if name == self.vertex_arrays.bound {
            return;
        }
        let v = &mut self.vertex_arrays;
        let mut incoming = std::mem::take(match name {
            0 => &mut v.default,
            n => v.names.get_or_create(n),
        });
        swap_pointers(&mut self.arrays, &mut incoming.arrays);
        std::mem::swap(&mut self.buffers.element_array, &mut incoming.element_array);
        // `incoming` now holds the state of the object that was bound.
        let v = &mut self.vertex_arrays;
        match v.bound {
            0 => v.default = incoming,
            old => *v.names.get_or_create(old) = incoming,
        }
        v.bound = name;
    }

    /// `glDeleteVertexArraysOES`: deleting the bound object binds 0 first; 0 and unknown
    /// names are ignored.
    pub fn delete_vertex_arrays(&mut self, n: i32, names: &[GLuint]) {
        if n < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        for &name in names {
            if name == 0 {
                continue;
            }
            if name == self.vertex_arrays.bound {
                self.bind_vertex_array(0);
            }
            self.vertex_arrays.names.remove(name);
        }
    }

    /// `glIsVertexArrayOES`: true for names bound at least once and not deleted.
    pub fn is_vertex_array(&self, name: GLuint) -> bool {
        self.vertex_arrays.names.get(name).is_some()
    }

    pub(super) fn vertex_array_value(&self, pname: GLenum) -> Option<Value> {
        (pname == GL_VERTEX_ARRAY_BINDING_OES).then(|| Value::int(self.vertex_arrays.bound as i64))
    }
}
