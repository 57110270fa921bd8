//! Buffer objects (ES 1.1 §2.9), `OES_mapbuffer` and `EXT_map_buffer_range`.
//!
//! Buffers live in the share group's [`SharedObjects`]; each context keeps its own
//! `ARRAY_BUFFER` / `ELEMENT_ARRAY_BUFFER` bindings, and every `gl*Pointer` call records the
//! name bound to `ARRAY_BUFFER` at that moment (its pointer then is an offset into that
//! buffer). Draws read buffer contents with bounds checks: a draw whose arrays or indices
//! would reach past the end of a buffer (or whose buffer no longer exists) is skipped
//! without an error, never reading outside the storage.
//!
//! A mapped buffer's storage never moves: `glBufferSubData` on a mapped buffer is
//! `GL_INVALID_OPERATION`, and `glBufferData` unmaps before it replaces the storage.
#![forbid(unsafe_code)]

use super::context::{Context, SharedObjects};
use super::get::Value;
use super::objects::{Binding, Names};
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// One buffer object's data store and state.
#[derive(Debug)]
pub struct Buffer {
    data: Vec<u8>,
    pub usage: GLenum,
    mapped: bool,
    /// The mapped range (offset, length) and its access bits (`EXT_map_buffer_range`;
    /// `glMapBufferOES` maps everything for writing).
    map_range: (usize, usize),
    map_access: GLbitfield,
}

impl Default for Buffer {
    fn default() -> Buffer {
        Buffer {
            data: Vec::new(),
            usage: GL_STATIC_DRAW,
            mapped: false,
            map_range: (0, 0),
            map_access: 0,
        }
    }
}

/// Every access bit `glMapBufferRangeEXT` knows.
const MAP_BITS: GLbitfield = GL_MAP_READ_BIT_EXT
    | GL_MAP_WRITE_BIT_EXT
    | GL_MAP_INVALIDATE_RANGE_BIT_EXT
    | GL_MAP_INVALIDATE_BUFFER_BIT_EXT
    | GL_MAP_FLUSH_EXPLICIT_BIT_EXT
    | GL_MAP_UNSYNCHRONIZED_BIT_EXT;

impl Buffer {
    pub fn data(&self) -> &[u8] {
        &self.data
    }

    pub fn is_mapped(&self) -> bool {
        self.mapped
    }

    /// `len` bytes at `offset`, or `None` when any of them lies outside the store.
    pub fn range(&self, offset: usize, len: usize) -> Option<&[u8]> {
        self.data.get(offset..offset.checked_add(len)?)
    }
}

/// The buffer objects of a share group.
pub type BufferNames = Names<Buffer>;

/// A context's buffer bindings.
#[derive(Clone, Debug, Default)]
pub struct BufferBindings {
    pub array: Binding,
    pub element_array: Binding,
}

impl Context {
    fn binding(&mut self, target: GLenum) -> Option<&mut Binding> {
        match target {
            GL_ARRAY_BUFFER => Some(&mut self.buffers.array),
            GL_ELEMENT_ARRAY_BUFFER => Some(&mut self.buffers.element_array),
            _ => {
                self.bad_enum("target", target);
                None
            }
        }
    }

    fn objects(&self) -> std::sync::MutexGuard<'_, SharedObjects> {
        lock_objects(&self.shared)
    }

    pub fn gen_buffers(&mut self, n: i32) -> Vec<GLuint> {
        if n < 0 {
            self.bad_value("n", n as i64, "n must not be negative");
            return Vec::new();
        }
        let mut o = self.objects();
        (0..n).map(|_| o.buffers.generate()).collect()
    }

    /// `glDeleteBuffers(n, names)` (`names` holds the `n` names; a negative `n` is
    /// `GL_INVALID_VALUE`). Unknown names and 0 are ignored; a deleted buffer is unbound from
    /// this context's targets and from every array pointer that references it. Other
    /// contexts that have it bound keep it (see [`super::objects`]).
    pub fn delete_buffers(&mut self, n: i32, names: &[GLuint]) {
        if n < 0 {
            return self.bad_value("n", n as i64, "n must not be negative");
        }
        self.forget_labels(super::tokens_ext::GL_BUFFER_KHR, names);
        let shared = self.shared.clone();
        let mut o = lock_objects(&shared);
        for &name in names {
            let Some(gone) = o.buffers.delete(name) else {
                continue;
            };
            for b in [&mut self.buffers.array, &mut self.buffers.element_array] {
                if b.same_object(&gone) {
                    *b = Binding::NONE;
                }
            }
            self.arrays.for_each_pointer(|p| {
                if p.buffer.same_object(&gone) {
                    p.buffer = Binding::NONE;
                }
            });
        }
        o.buffers.sweep();
    }

    pub fn bind_buffer(&mut self, target: GLenum, name: GLuint) {
        if self.binding(target).is_none() {
            return;
        }
        let b = self.objects().buffers.bind(name, Buffer::default);
        *self.binding(target).expect("checked") = b;
    }

    pub fn is_buffer(&mut self, name: GLuint) -> bool {
        self.objects().buffers.named(name).is_some()
    }

    /// Validates the target of a data call and returns the bound buffer, raising
    /// `GL_INVALID_OPERATION` when none is bound.
    fn bound_buffer(&mut self, target: GLenum) -> Option<Binding> {
        let b = self.binding(target)?.clone();
        if b.is_none() {
            self.bad_operation("no buffer object is bound to target (name 0 is bound)");
            return None;
        }
        Some(b)
    }

    /// `glBufferData`: `data` is `None` for a null pointer (the store is then zeroed).
    pub fn buffer_data(&mut self, target: GLenum, size: isize, data: Option<&[u8]>, usage: GLenum) {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            return self.bad_enum("target", target);
        }
        // ES 1.1 has only the static and dynamic hints (no STREAM_DRAW).
        if !matches!(usage, GL_STATIC_DRAW | GL_DYNAMIC_DRAW) {
            return self.bad_enum("usage", usage);
        }
        if size < 0 {
            return self.bad_value("size", size as i64, "size must not be negative");
        }
        let Some(bound) = self.bound_buffer(target) else {
            return;
        };
        let size = size as usize;
        let mut store = Vec::new();
        if store.try_reserve_exact(size).is_err() {
            return self.set_error(GL_OUT_OF_MEMORY);
        }
        match data {
            Some(d) => store.extend_from_slice(&d[..size]),
            None => store.resize(size, 0),
        }
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        b.data = store;
        b.usage = usage;
        b.mapped = false;
    }

    /// `glBufferSubData`: the range must lie inside the store (`GL_INVALID_VALUE`) and the
    /// buffer must not be mapped (`GL_INVALID_OPERATION`).
    pub fn buffer_sub_data(&mut self, target: GLenum, offset: isize, data: &[u8]) {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            return self.bad_enum("target", target);
        }
        let Some(bound) = self.bound_buffer(target) else {
            return;
        };
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        let end = (offset as usize).checked_add(data.len());
        if offset < 0 || end.is_none_or(|e| e > b.data.len()) {
            drop(o);
            return self.bad_value(
                "offset",
                offset as i64,
                "offset + size must lie within the buffer's store",
            );
        }
        if b.mapped {
            drop(o);
            return self.bad_operation("the buffer is mapped; unmap it first");
        }
        b.data[offset as usize..][..data.len()].copy_from_slice(data);
    }

    /// `glGetBufferParameteriv`.
    pub fn buffer_parameter(&mut self, target: GLenum, pname: GLenum) -> Option<GLint> {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            self.bad_enum("target", target);
            return None;
        }
        if !matches!(
            pname,
            GL_BUFFER_SIZE | GL_BUFFER_USAGE | GL_BUFFER_ACCESS_OES | GL_BUFFER_MAPPED_OES
        ) {
            self.bad_enum("pname", pname);
            return None;
        }
        let bound = self.bound_buffer(target)?;
        let o = self.objects();
        let b = o.buffers.get(&bound).expect("bound objects live");
        Some(match pname {
            GL_BUFFER_SIZE => b.data.len().min(i32::MAX as usize) as GLint,
            GL_BUFFER_USAGE => b.usage as GLint,
            GL_BUFFER_ACCESS_OES => GL_WRITE_ONLY_OES as GLint,
            _ => GLint::from(b.mapped),
        })
    }

    /// `glMapBufferOES`: a pointer to the bound buffer's store, valid until it is unmapped,
    /// respecified or deleted. An empty store maps to a dangling but non-null pointer.
    pub fn map_buffer(&mut self, target: GLenum, access: GLenum) -> Option<*mut u8> {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER)
            || access != GL_WRITE_ONLY_OES
        {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let bound = self.bound_buffer(target)?;
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        if b.mapped {
            drop(o);
            self.bad_operation("the buffer is already mapped");
            return None;
        }
        b.mapped = true;
        b.map_range = (0, b.data.len());
        b.map_access = GL_MAP_WRITE_BIT_EXT;
        Some(b.data.as_mut_ptr())
    }

    /// `glMapBufferRangeEXT`: a pointer to `length` bytes at `offset` of the bound buffer's
    /// store (which never moves while mapped). The store is always readable and keeps its
    /// contents, so the invalidate and unsynchronized bits change nothing here.
    pub fn map_buffer_range(
        &mut self,
        target: GLenum,
        offset: isize,
        length: isize,
        access: GLbitfield,
    ) -> Option<*mut u8> {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            self.bad_enum("target", target);
            return None;
        }
        let read = access & GL_MAP_READ_BIT_EXT != 0;
        let write = access & GL_MAP_WRITE_BIT_EXT != 0;
        let read_only_conflict = GL_MAP_INVALIDATE_RANGE_BIT_EXT
            | GL_MAP_INVALIDATE_BUFFER_BIT_EXT
            | GL_MAP_UNSYNCHRONIZED_BIT_EXT;
        if offset < 0 || length < 0 || access & !MAP_BITS != 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let bound = self.bound_buffer(target)?;
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        let (offset, length) = (offset as usize, length as usize);
        let error = if offset
            .checked_add(length)
            .is_none_or(|end| end > b.data.len())
        {
            Some(GL_INVALID_VALUE)
        } else if b.mapped
            || length == 0
            || !(read || write)
            || (read && access & read_only_conflict != 0)
            || (!write && access & GL_MAP_FLUSH_EXPLICIT_BIT_EXT != 0)
        {
            Some(GL_INVALID_OPERATION)
        } else {
            None
        };
        if let Some(e) = error {
            drop(o);
            self.set_error(e);
            return None;
        }
        b.mapped = true;
        b.map_range = (offset, length);
        b.map_access = access;
        Some(b.data[offset..].as_mut_ptr())
    }

    /// `glFlushMappedBufferRangeEXT`: the store is the mapping, so flushing only validates
    /// (a range within the mapping, a mapping made with `GL_MAP_FLUSH_EXPLICIT_BIT_EXT`).
    pub fn flush_mapped_buffer_range(&mut self, target: GLenum, offset: isize, length: isize) {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            return self.bad_enum("target", target);
        }
        if offset < 0 || length < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(bound) = self.bound_buffer(target) else {
            return;
        };
        let o = self.objects();
        let b = o.buffers.get(&bound).expect("bound objects live");
        let error = if !b.mapped || b.map_access & GL_MAP_FLUSH_EXPLICIT_BIT_EXT == 0 {
            Some(GL_INVALID_OPERATION)
        } else if (offset as usize).saturating_add(length as usize) > b.map_range.1 {
            Some(GL_INVALID_VALUE)
        } else {
            None
        };
        drop(o);
        if let Some(e) = error {
            self.set_error(e);
        }
    }

    /// `glUnmapBufferOES`: true unless the buffer was not mapped (`GL_INVALID_OPERATION`).
    pub fn unmap_buffer(&mut self, target: GLenum) -> bool {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER) {
            self.bad_enum("target", target);
            return false;
        }
        let Some(bound) = self.bound_buffer(target) else {
            return false;
        };
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        if !b.mapped {
            drop(o);
            self.bad_operation("the buffer is not mapped");
            return false;
        }
        b.mapped = false;
        true
    }

    /// `glGetBufferPointervOES(target, GL_BUFFER_MAP_POINTER_OES)`: the mapped pointer, or
    /// null when the buffer is not mapped. `None` after an error.
    pub fn buffer_pointer(&mut self, target: GLenum, pname: GLenum) -> Option<*mut u8> {
        if !matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER)
            || pname != GL_BUFFER_MAP_POINTER_OES
        {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let bound = self.bound_buffer(target)?;
        let mut o = self.objects();
        let b = o.buffers.get_mut(&bound).expect("bound objects live");
        Some(if b.mapped {
            b.data[b.map_range.0..].as_mut_ptr()
        } else {
            std::ptr::null_mut()
        })
    }
}

impl Context {
    /// The buffer bindings `glGet*` reports.
    pub(super) fn buffer_value(&mut self, pname: GLenum) -> Option<Value> {
        let a = &self.arrays;
        let name = match pname {
            GL_ARRAY_BUFFER_BINDING => self.buffers.array.name,
            GL_ELEMENT_ARRAY_BUFFER_BINDING => self.buffers.element_array.name,
            GL_VERTEX_ARRAY_BUFFER_BINDING => a.vertex.buffer.name,
            GL_NORMAL_ARRAY_BUFFER_BINDING => a.normal.buffer.name,
            GL_COLOR_ARRAY_BUFFER_BINDING => a.color.buffer.name,
            GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => {
                a.texcoord[a.client_active_texture].buffer.name
            }
            GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES => a.point_size.buffer.name,
            _ => return None,
        };
        Some(Value::int(name as i64))
    }
}

/// Locks a share group's objects, recovering from a lock poisoned by a caught panic.
pub(super) fn lock_objects(
    shared: &std::sync::Mutex<SharedObjects>,
) -> std::sync::MutexGuard<'_, SharedObjects> {
    shared.lock().unwrap_or_else(|e| e.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_bounds_checked() {
        let b = Buffer {
            data: vec![1, 2, 3, 4],
            ..Buffer::default()
        };
        assert_eq!(b.range(1, 3), Some(&[2, 3, 4][..]));
        assert_eq!(b.range(4, 0), Some(&[][..]));
        assert_eq!(b.range(2, 3), None);
        assert_eq!(b.range(5, 0), None);
        assert_eq!(b.range(usize::MAX, 2), None);
    }
}

#[cfg(test)]
mod context_tests {
    use std::sync::{Arc, Mutex};

    use super::lock_objects;
    use crate::gles::arrays::ArrayKind;
    use crate::gles::context::{Context, Surface};
    use crate::gles::ffi::ClientPtr;
    use crate::gles::tokens::*;
    use crate::gles::tokens_ext::*;
    use gles_cm_core::{ColorFormat, Target, TargetFormat};

    struct Memory(Mutex<Target>);

    impl Surface for Memory {
        fn target(&self) -> &Mutex<Target> {
            &self.0
        }
    }

    fn context() -> (Context, Arc<Memory>) {
        let s = Arc::new(Memory(Mutex::new(Target::new(
            8,
            8,
            TargetFormat {
                color: ColorFormat::Rgba8888,
                depth: None,
                stencil_bits: 0,
            },
        ))));
        let mut c = Context::new(None);
        c.make_current(Some(s.clone()), Some(s.clone()));
        (c, s)
    }

    fn floats(v: &[f32]) -> Vec<u8> {
        v.iter().flat_map(|f| f.to_ne_bytes()).collect()
    }

    /// A full-viewport triangle pair's worth of vertices (x, y) in a buffer object.
    fn quad(c: &mut Context) -> u32 {
        let name = c.gen_buffers(1)[0];
        c.bind_buffer(GL_ARRAY_BUFFER, name);
        let v = floats(&[-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0]);
        c.buffer_data(GL_ARRAY_BUFFER, v.len() as isize, Some(&v), GL_STATIC_DRAW);
        c.array_pointer(ArrayKind::Vertex, 2, GL_FLOAT, 0, ClientPtr::offset(0));
        c.client_state(GL_VERTEX_ARRAY, true);
        name
    }

    #[test]
    fn data_errors() {
        let (mut c, _) = context();
        c.buffer_data(GL_ARRAY_BUFFER, 4, None, GL_STATIC_DRAW);
        assert_eq!(c.take_error(), GL_INVALID_OPERATION, "nothing bound");
        let b = c.gen_buffers(1)[0];
        assert!(!c.is_buffer(b), "generated but never bound");
        c.bind_buffer(GL_ARRAY_BUFFER, b);
        assert!(c.is_buffer(b));
        c.buffer_data(GL_ARRAY_BUFFER, 4, None, 0x88E0); // GL_STREAM_DRAW
        assert_eq!(c.take_error(), GL_INVALID_ENUM, "no STREAM_DRAW in ES 1.1");
        c.buffer_data(GL_ARRAY_BUFFER, -1, None, GL_STATIC_DRAW);
        assert_eq!(c.take_error(), GL_INVALID_VALUE);
        c.buffer_data(GL_ARRAY_BUFFER, 4, Some(&[1, 2, 3, 4]), GL_DYNAMIC_DRAW);
        assert_eq!(c.take_error(), GL_NO_ERROR);
        c.buffer_sub_data(GL_ARRAY_BUFFER, 2, &[9, 9, 9]);
        assert_eq!(c.take_error(), GL_INVALID_VALUE);
        c.buffer_sub_data(GL_ARRAY_BUFFER, -1, &[]);
        assert_eq!(c.take_error(), GL_INVALID_VALUE);
        c.buffer_sub_data(GL_ARRAY_BUFFER, 2, &[7, 8]);
        assert_eq!(c.take_error(), GL_NO_ERROR);
        assert_eq!(c.buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_SIZE), Some(4));
        assert_eq!(
            c.buffer_parameter(GL_ARRAY_BUFFER, GL_BUFFER_USAGE),
            Some(GL_DYNAMIC_DRAW as i32)
        );
        // Writes through the mapping: `ffi::buffer`'s tests (this module has no `unsafe`).
        let p = c.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES).unwrap();
        c.buffer_sub_data(GL_ARRAY_BUFFER, 0, &[1]);
        assert_eq!(c.take_error(), GL_INVALID_OPERATION, "mapped");
        assert_eq!(c.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY_OES), None);
        assert_eq!(c.take_error(), GL_INVALID_OPERATION);
        assert_eq!(
            c.buffer_pointer(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER_OES),
            Some(p)
        );
        assert!(c.unmap_buffer(GL_ARRAY_BUFFER));
        assert!(!c.unmap_buffer(GL_ARRAY_BUFFER));
        assert_eq!(c.take_error(), GL_INVALID_OPERATION);
        let o = lock_objects(&c.shared);
        assert_eq!(o.buffers.named(b).unwrap().data(), &[1, 2, 7, 8]);
    }

    #[test]
    fn out_of_range_draws_are_skipped() {
        let (mut c, s) = context();
        quad(&mut c);
        c.draw_arrays(GL_TRIANGLE_STRIP, 0, 5);
        c.flush();
        assert_eq!(c.take_error(), GL_NO_ERROR);
        assert_eq!(s.0.lock().unwrap().pixel(4, 4), [0, 0, 0, 0], "skipped");
        // An offset past the end is skipped too.
        c.array_pointer(
            ArrayKind::Vertex,
            2,
            GL_FLOAT,
            0,
            ClientPtr::offset(1 << 40),
        );
        c.draw_arrays(GL_TRIANGLE_STRIP, 0, 1);
        c.array_pointer(ArrayKind::Vertex, 2, GL_FLOAT, 0, ClientPtr::offset(0));
        // Element buffer indices past the vertex data, and past the element buffer.
        let e = c.gen_buffers(1)[0];
        c.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, e);
        c.buffer_data(
            GL_ELEMENT_ARRAY_BUFFER,
            4,
            Some(&[0, 1, 2, 200]),
            GL_STATIC_DRAW,
        );
        c.draw_elements_from_buffer(GL_TRIANGLE_STRIP, 4, 1, 0);
        c.draw_elements_from_buffer(GL_TRIANGLE_STRIP, 4, 1, 1);
        c.draw_elements_from_buffer(GL_TRIANGLE_STRIP, 2, 2, usize::MAX);
        c.flush();
        assert_eq!(c.take_error(), GL_NO_ERROR);
        assert_eq!(s.0.lock().unwrap().pixel(4, 4), [0, 0, 0, 0]);
        // In range, it draws.
        c.draw_elements_from_buffer(GL_TRIANGLES, 3, 1, 0);
        c.draw_arrays(GL_TRIANGLE_STRIP, 0, 4);
        c.flush();
        assert_eq!(s.0.lock().unwrap().pixel(4, 4), [255, 255, 255, 255]);
    }

    #[test]
    fn deleting_unbinds_everywhere_in_the_context() {
        let (mut c, _) = context();
        let b = quad(&mut c);
        c.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, b);
        let val = |c: &mut Context, p| c.state_value(p).unwrap().values()[0] as u32;
        assert_eq!(val(&mut c, GL_VERTEX_ARRAY_BUFFER_BINDING), b);
        c.delete_buffers(-1, &[]);
        assert_eq!(c.take_error(), GL_INVALID_VALUE);
        c.delete_buffers(2, &[0, b]);
        assert_eq!(val(&mut c, GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
        assert_eq!(val(&mut c, GL_ARRAY_BUFFER_BINDING), 0);
        assert_eq!(val(&mut c, GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
        assert!(!c.is_buffer(b));
    }

    #[test]
    fn share_groups_see_the_same_objects() {
        let (mut a, _) = context();
        let mut shared = Context::new(Some(&a));
        let mut alone = Context::new(None);
        let b = a.gen_buffers(1)[0];
        a.bind_buffer(GL_ARRAY_BUFFER, b);
        a.bind_texture(GL_TEXTURE_2D, 7);
        assert!(shared.is_buffer(b) && shared.is_texture(7));
        assert!(!alone.is_buffer(b) && !alone.is_texture(7));
    }
}
