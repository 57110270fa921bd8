//! `GL_KHR_debug`: debug messages (the message log, the callback, message control, debug
//! groups) and object labels, with the ES names of the extension (`...KHR`).
//!
//! Every GL error the library records also becomes a message (source API, type ERROR,
//! severity HIGH, the error code as its id) that says in words which call failed and why:
//! the entry point's name comes from the C boundary (`Context::call`), the argument, its
//! value and the broken rule from the validation that failed ([`Why`]). Nothing is formatted
//! unless debug output is enabled and the message passes message control.
//!
//! `GL_DEBUG_OUTPUT_KHR` starts enabled in debug contexts (EGL 1.5's
//! `EGL_CONTEXT_OPENGL_DEBUG`, `EGL_KHR_create_context`'s debug flag) and disabled in others,
//! as the extension says; once it is enabled, every message is generated. Messages are always delivered
//! synchronously (before the call that caused them returns), whatever
//! `GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR` says. The callback runs after the context is unlocked,
//! so one that calls GL does not deadlock.
#![forbid(unsafe_code)]

use std::collections::{HashMap, VecDeque};
use std::ffi::c_void;
use std::fmt::{self, Write as _};
use std::sync::OnceLock;

use super::buffer::lock_objects;
use super::context::Context;
use super::tokens::*;
use super::tokens_ext::*;
use super::types::*;

/// The callback an application installs with `glDebugMessageCallbackKHR`.
pub type GLDEBUGPROCKHR = Option<
    unsafe extern "C" fn(
        source: GLenum,
        ty: GLenum,
        id: GLuint,
        severity: GLenum,
        length: GLsizei,
        message: *const GLchar,
        user_param: *const c_void,
    ),
>;

/// Longest message, terminator included (the extension's minimum is 1).
pub const MAX_DEBUG_MESSAGE_LENGTH: usize = 1024;
/// Messages the log keeps; later ones are dropped while it is full.
pub const MAX_DEBUG_LOGGED_MESSAGES: usize = 64;
/// Debug groups, the default one included (the extension's minimum).
pub const MAX_DEBUG_GROUP_STACK_DEPTH: usize = 64;
/// Longest object label, terminator included (the extension's minimum).
pub const MAX_LABEL_LENGTH: usize = 256;

/// Why a call failed, in the terms of its validation: which argument, which value, which
/// rule. Cheap to build (no formatting until a message is wanted).
#[derive(Clone, Copy, Debug)]
pub enum Why {
    /// `arg` is an enum the call does not accept there.
    Enum(&'static str, GLenum),
    /// `arg` is `value`, which breaks `rule` (said as what must hold).
    Value(&'static str, i64, &'static str),
    /// `arg` is enum `value`, which breaks `rule`.
    EnumRule(&'static str, GLenum, &'static str),
    /// The state of the context breaks `rule`.
    Rule(&'static str),
}

/// One debug message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Message {
    pub source: GLenum,
    pub ty: GLenum,
    pub id: GLuint,
    pub severity: GLenum,
    pub text: String,
}

/// A `glDebugMessageControlKHR` call: `None` for `GL_DONT_CARE`.
#[derive(Clone, Debug)]
struct Rule {
    source: Option<GLenum>,
    ty: Option<GLenum>,
    severity: Option<GLenum>,
    ids: Option<Vec<GLuint>>,
    enabled: bool,
}

impl Rule {
    fn matches(&self, m: &Message) -> bool {
        self.source.is_none_or(|s| s == m.source)
            && self.ty.is_none_or(|t| t == m.ty)
            && self.severity.is_none_or(|s| s == m.severity)
            && self.ids.as_ref().is_none_or(|ids| ids.contains(&m.id))
    }

    /// True when every message `other` matches, `self` matches too.
    fn covers(&self, other: &Rule) -> bool {
        fn field(a: Option<GLenum>, b: Option<GLenum>) -> bool {
            a.is_none() || a == b
        }
        field(self.source, other.source)
            && field(self.ty, other.ty)
            && field(self.severity, other.severity)
            && match (&self.ids, &other.ids) {
                (None, _) => true,
                (Some(a), Some(b)) => b.iter().all(|id| a.contains(id)),
                (Some(_), None) => false,
            }
    }
}

/// A debug group: the message its push generated and its message control state.
#[derive(Clone, Debug)]
struct Group {
    push: Option<Message>,
    /// The control calls made in this group (and inherited), oldest first: the last one
    /// that matches a message decides.
    rules: Vec<Rule>,
}

/// The debug state of one context.
pub struct Debug {
    /// `GL_DEBUG_OUTPUT_KHR`.
    pub output: bool,
    /// `GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR` (delivery is synchronous either way).
    pub synchronous: bool,
    pub callback: GLDEBUGPROCKHR,
    pub user_param: usize,
    log: VecDeque<Message>,
    groups: Vec<Group>,
    /// Messages for the callback, delivered once the context is unlocked.
    pending: Vec<Message>,
    /// Labels of framebuffer and vertex array objects (per context objects).
    labels: HashMap<(GLenum, GLuint), String>,
}

impl Default for Debug {
    fn default() -> Debug {
        Debug {
            output: false,
            synchronous: false,
            callback: None,
            user_param: 0,
            log: VecDeque::new(),
            groups: vec![Group {
                push: None,
                rules: Vec::new(),
            }],
            pending: Vec::new(),
            labels: HashMap::new(),
        }
    }
}

impl Debug {
    /// True when a message with these properties would be delivered now.
    pub fn wants(&self, source: GLenum, ty: GLenum, id: GLuint, severity: GLenum) -> bool {
        if !self.output {
            return false;
        }
        let probe = Message {
            source,
            ty,
            id,
            severity,
            text: String::new(),
        };
        let rules = &self.groups.last().map_or(&[][..], |g| &g.rules[..]);
        match rules.iter().rev().find(|r| r.matches(&probe)) {
            Some(r) => r.enabled,
            // Every message starts enabled except those of low severity.
            None => severity != GL_DEBUG_SEVERITY_LOW_KHR,
        }
    }

    /// Delivers `m` (already found wanted): to the callback if there is one, else to the
    /// log while it has room.
    fn deliver(&mut self, mut m: Message) {
        truncate(&mut m.text, MAX_DEBUG_MESSAGE_LENGTH - 1);
        if self.callback.is_some() {
            self.pending.push(m);
        } else if self.log.len() < MAX_DEBUG_LOGGED_MESSAGES {
            self.log.push_back(m);
        }
    }

    /// Generates a message if message control lets it through.
    pub fn message(&mut self, m: Message) {
        if self.wants(m.source, m.ty, m.id, m.severity) {
            self.deliver(m);
        }
    }

    /// The messages waiting for the callback, with the callback and its parameter.
    pub fn take_pending(&mut self) -> Option<(GLDEBUGPROCKHR, usize, Vec<Message>)> {
        if self.pending.is_empty() {
            return None;
        }
        Some((
            self.callback,
            self.user_param,
            std::mem::take(&mut self.pending),
        ))
    }

    /// Messages in the log.
    pub fn logged(&self) -> usize {
        self.log.len()
    }

    /// Length of the oldest logged message with its terminator, 0 for an empty log.
    pub fn next_length(&self) -> usize {
        self.log.front().map_or(0, |m| m.text.len() + 1)
    }

    /// Debug groups on the stack, the default one included.
    pub fn depth(&self) -> usize {
        self.groups.len()
    }
}

/// Cuts `s` to at most `max` bytes, at a character boundary.
fn truncate(s: &mut String, max: usize) {
    if s.len() > max {
        let mut end = max;
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        s.truncate(end);
    }
}

/// The name of every token this library knows, by value (the first one written, core
/// tokens before extension ones), read once from the token sources.
fn token_name(value: GLenum) -> Option<&'static str> {
    static NAMES: OnceLock<HashMap<GLenum, &'static str>> = OnceLock::new();
    NAMES
        .get_or_init(|| {
            let mut map = HashMap::new();
            for src in [include_str!("tokens.rs"), include_str!("tokens_ext.rs")] {
                for line in src.lines() {
                    let Some(rest) = line.trim().strip_prefix("pub const ") else {
                        continue;
                    };
                    let Some((name, rest)) = rest.split_once(':') else {
                        continue;
                    };
                    let Some((_, v)) = rest.split_once('=') else {
                        continue;
                    };
                    let v = v.trim().trim_end_matches(';').trim();
                    let parsed = match v.strip_prefix("0x") {
                        Some(h) => u32::from_str_radix(h, 16).ok(),
                        None => v.parse().ok(),
                    };
                    if let Some(v) = parsed {
                        map.entry(v).or_insert(name.trim());
                    }
                }
            }
            map
        })
        .get(&value)
        .copied()
}

/// An enum value in words: `0x0DE1 (GL_TEXTURE_2D)`, or the hex value alone when it is no
/// token of ours.
pub struct EnumName(pub GLenum);

impl fmt::Display for EnumName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match token_name(self.0) {
            Some(n) => write!(f, "0x{:04X} ({n})", self.0),
            None => write!(f, "0x{:04X} (not a token of this implementation)", self.0),
        }
    }
}

/// What an error code means when nothing more specific is known.
fn generic(e: GLenum) -> &'static str {
    match e {
        GL_INVALID_ENUM => "an enumerated argument is not one this call accepts",
        GL_INVALID_VALUE => "a numeric argument is out of range",
        GL_INVALID_OPERATION => "the call is not allowed in the current state",
        GL_STACK_OVERFLOW => "the call would overflow a stack",
        GL_STACK_UNDERFLOW => "the call would underflow a stack",
        GL_OUT_OF_MEMORY => "there is not enough memory left to execute the call",
        GL_INVALID_FRAMEBUFFER_OPERATION_OES => "the bound framebuffer is not complete",
        _ => "the call failed",
    }
}

/// The text of the message for error `e` raised by `call`.
pub fn error_text(call: &str, e: GLenum, why: Option<Why>) -> String {
    let mut s = String::new();
    let code = token_name(e).unwrap_or("GL error");
    let _ = write!(s, "{call}: {code} (0x{e:04X}): ");
    let _ = match why {
        None => write!(s, "{}", generic(e)),
        Some(Why::Enum(arg, v)) => write!(
            s,
            "{arg} is {}, which is not a value this call accepts for {arg}",
            EnumName(v)
        ),
        Some(Why::Value(arg, v, rule)) => write!(s, "{arg} is {v}, but {rule}"),
        Some(Why::EnumRule(arg, v, rule)) => write!(s, "{arg} is {}, but {rule}", EnumName(v)),
        Some(Why::Rule(rule)) => write!(s, "{rule}"),
    };
    s
}

/// The object namespaces of `glObjectLabelKHR` in OpenGL ES 1.1 (with
/// `OES_framebuffer_object` and `OES_vertex_array_object`). Shader, program, query, program
/// pipeline and sampler objects do not exist here: `GL_INVALID_ENUM`.
fn namespace(identifier: GLenum) -> Option<&'static str> {
    Some(match identifier {
        GL_BUFFER_KHR => "buffer",
        GL_TEXTURE => "texture",
        GL_RENDERBUFFER_OES => "renderbuffer",
        GL_FRAMEBUFFER_OES => "framebuffer",
        GL_VERTEX_ARRAY_KHR => "vertex array",
        _ => return None,
    })
}

fn is_source(v: GLenum) -> bool {
    matches!(
        v,
        GL_DEBUG_SOURCE_API_KHR
            | GL_DEBUG_SOURCE_WINDOW_SYSTEM_KHR
            | GL_DEBUG_SOURCE_SHADER_COMPILER_KHR
            | GL_DEBUG_SOURCE_THIRD_PARTY_KHR
            | GL_DEBUG_SOURCE_APPLICATION_KHR
            | GL_DEBUG_SOURCE_OTHER_KHR
    )
}

fn is_type(v: GLenum) -> bool {
    matches!(
        v,
        GL_DEBUG_TYPE_ERROR_KHR
            | GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR_KHR
            | GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR_KHR
            | GL_DEBUG_TYPE_PORTABILITY_KHR
            | GL_DEBUG_TYPE_PERFORMANCE_KHR
            | GL_DEBUG_TYPE_OTHER_KHR
            | GL_DEBUG_TYPE_MARKER_KHR
            | GL_DEBUG_TYPE_PUSH_GROUP_KHR
            | GL_DEBUG_TYPE_POP_GROUP_KHR
    )
}

fn is_severity(v: GLenum) -> bool {
    matches!(
        v,
        GL_DEBUG_SEVERITY_HIGH_KHR
            | GL_DEBUG_SEVERITY_MEDIUM_KHR
            | GL_DEBUG_SEVERITY_LOW_KHR
            | GL_DEBUG_SEVERITY_NOTIFICATION_KHR
    )
}

/// One message fetched by `glGetDebugMessageLogKHR`.
pub type Fetched = Message;

impl Context {
    /// Records error `e` for the current call, and says why in a debug message when one is
    /// wanted.
    pub fn fail(&mut self, e: GLenum, why: Why) {
        self.raise(e, Some(why));
    }

    /// `GL_INVALID_ENUM` for argument `arg` holding `value`.
    pub fn bad_enum(&mut self, arg: &'static str, value: GLenum) {
        self.raise(GL_INVALID_ENUM, Some(Why::Enum(arg, value)));
    }

    /// `GL_INVALID_VALUE` for argument `arg` holding `value`, which breaks `rule`.
    pub fn bad_value(&mut self, arg: &'static str, value: i64, rule: &'static str) {
        self.raise(GL_INVALID_VALUE, Some(Why::Value(arg, value, rule)));
    }

    /// `GL_INVALID_OPERATION` because of `rule`.
    pub fn bad_operation(&mut self, rule: &'static str) {
        self.raise(GL_INVALID_OPERATION, Some(Why::Rule(rule)));
    }

    /// Records `e` (the first error stays until read) and generates its message.
    pub(super) fn raise(&mut self, e: GLenum, why: Option<Why>) {
        if self.error == GL_NO_ERROR {
            self.error = e;
        }
        let (source, ty, severity) = (
            GL_DEBUG_SOURCE_API_KHR,
            GL_DEBUG_TYPE_ERROR_KHR,
            GL_DEBUG_SEVERITY_HIGH_KHR,
        );
        if self.debug.wants(source, ty, e, severity) {
            let text = error_text(self.call, e, why);
            self.debug.deliver(Message {
                source,
                ty,
                id: e,
                severity,
                text,
            });
        }
    }

    /// `glDebugMessageControlKHR`.
    pub fn debug_message_control(
        &mut self,
        source: GLenum,
        ty: GLenum,
        severity: GLenum,
        count: GLsizei,
        ids: &[GLuint],
        enabled: bool,
    ) {
        if source != GL_DONT_CARE && !is_source(source) {
            return self.bad_enum("source", source);
        }
        if ty != GL_DONT_CARE && !is_type(ty) {
            return self.bad_enum("type", ty);
        }
        if severity != GL_DONT_CARE && !is_severity(severity) {
            return self.bad_enum("severity", severity);
        }
        if count < 0 {
            return self.bad_value("count", count as i64, "count must not be negative");
        }
        if count > 0 {
            if source == GL_DONT_CARE || ty == GL_DONT_CARE {
                return self.bad_operation(
                    "ids are given (count > 0) but source or type is GL_DONT_CARE; ids name \
                     messages of one source and one type",
                );
            }
            if severity != GL_DONT_CARE {
                return self
                    .bad_operation("ids are given (count > 0) but severity is not GL_DONT_CARE");
            }
        }
        let some = |v: GLenum| (v != GL_DONT_CARE).then_some(v);
        let rule = Rule {
            source: some(source),
            ty: some(ty),
            severity: some(severity),
            ids: (count > 0).then(|| ids.to_vec()),
            enabled,
        };
        if let Some(g) = self.debug.groups.last_mut() {
            // Rules the new one overrides for every message they match are dropped, so
            // that repeated calls do not pile up.
            g.rules.retain(|r| !rule.covers(r));
            g.rules.push(rule);
        }
    }

    /// Checks an application message's length: `None` after an error.
    fn app_text(&mut self, length: GLsizei, text: &[u8], arg: &'static str) -> Option<String> {
        if text.len() >= MAX_DEBUG_MESSAGE_LENGTH {
            self.bad_value(
                if length < 0 { "the length of buf" } else { arg },
                text.len() as i64,
                "a message must be shorter than GL_MAX_DEBUG_MESSAGE_LENGTH_KHR (1024)",
            );
            return None;
        }
        Some(String::from_utf8_lossy(text).into_owned())
    }

    /// `glDebugMessageInsertKHR`; `text` is the message without a terminator (`length`
    /// negative: it was found by its terminator).
    pub fn debug_message_insert(
        &mut self,
        source: GLenum,
        ty: GLenum,
        id: GLuint,
        severity: GLenum,
        length: GLsizei,
        text: &[u8],
    ) {
        if !matches!(
            source,
            GL_DEBUG_SOURCE_APPLICATION_KHR | GL_DEBUG_SOURCE_THIRD_PARTY_KHR
        ) {
            return self.fail(
                GL_INVALID_ENUM,
                Why::EnumRule(
                    "source",
                    source,
                    "an inserted message's source must be GL_DEBUG_SOURCE_APPLICATION_KHR \
                     (0x824A) or GL_DEBUG_SOURCE_THIRD_PARTY_KHR (0x8249)",
                ),
            );
        }
        if !is_type(ty) {
            return self.bad_enum("type", ty);
        }
        if !is_severity(severity) {
            return self.bad_enum("severity", severity);
        }
        let Some(text) = self.app_text(length, text, "length") else {
            return;
        };
        self.debug.message(Message {
            source,
            ty,
            id,
            severity,
            text,
        });
    }

    /// `glGetDebugMessageLogKHR`: removes and returns up to `count` messages, stopping at
    /// the first whose text (with its terminator) does not fit in what is left of
    /// `buf_size` (no limit when the application passed no buffer).
    pub fn debug_message_log(&mut self, count: GLuint, buf_size: Option<GLsizei>) -> Vec<Fetched> {
        if let Some(b) = buf_size {
            if b < 0 {
                self.bad_value(
                    "bufSize",
                    b as i64,
                    "bufSize must not be negative when messageLog is not NULL",
                );
                return Vec::new();
            }
        }
        let mut left = buf_size.map(|b| b as usize);
        let mut out = Vec::new();
        while out.len() < count as usize {
            let Some(m) = self.debug.log.front() else {
                break;
            };
            let need = m.text.len() + 1;
            if let Some(l) = &mut left {
                if need > *l {
                    break;
                }
                *l -= need;
            }
            out.extend(self.debug.log.pop_front());
        }
        out
    }

    /// `glPushDebugGroupKHR`.
    pub fn push_debug_group(&mut self, source: GLenum, id: GLuint, length: GLsizei, text: &[u8]) {
        if !matches!(
            source,
            GL_DEBUG_SOURCE_APPLICATION_KHR | GL_DEBUG_SOURCE_THIRD_PARTY_KHR
        ) {
            return self.fail(
                GL_INVALID_ENUM,
                Why::EnumRule(
                    "source",
                    source,
                    "a debug group's source must be GL_DEBUG_SOURCE_APPLICATION_KHR (0x824A) \
                     or GL_DEBUG_SOURCE_THIRD_PARTY_KHR (0x8249)",
                ),
            );
        }
        let Some(text) = self.app_text(length, text, "length") else {
            return;
        };
        if self.debug.groups.len() >= MAX_DEBUG_GROUP_STACK_DEPTH {
            return self.fail(
                GL_STACK_OVERFLOW,
                Why::Rule(
                    "the debug group stack is full (GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR is 64, \
                     the default group included)",
                ),
            );
        }
        let m = Message {
            source,
            ty: GL_DEBUG_TYPE_PUSH_GROUP_KHR,
            id,
            severity: GL_DEBUG_SEVERITY_NOTIFICATION_KHR,
            text,
        };
        self.debug.message(m.clone());
        let rules = self
            .debug
            .groups
            .last()
            .map(|g| g.rules.clone())
            .unwrap_or_default();
        self.debug.groups.push(Group {
            push: Some(m),
            rules,
        });
    }

    /// `glPopDebugGroupKHR`.
    pub fn pop_debug_group(&mut self) {
        if self.debug.groups.len() <= 1 {
            return self.fail(
                GL_STACK_UNDERFLOW,
                Why::Rule("only the default debug group is on the stack, and it cannot be popped"),
            );
        }
        let Some(g) = self.debug.groups.pop() else {
            return;
        };
        if let Some(mut m) = g.push {
            // The pop message repeats the push's source, id and text, under the control
            // state the pop returns to.
            m.ty = GL_DEBUG_TYPE_POP_GROUP_KHR;
            self.debug.message(m);
        }
    }

    /// Checks `identifier` and `name` of an object label call: the namespace's noun, or
    /// `None` after an error.
    fn label_target(&mut self, identifier: GLenum, name: GLuint) -> Option<&'static str> {
        let Some(kind) = namespace(identifier) else {
            self.fail(
                GL_INVALID_ENUM,
                Why::EnumRule(
                    "identifier",
                    identifier,
                    "identifier must name an object namespace of OpenGL ES 1.1: GL_BUFFER_KHR, \
                     GL_TEXTURE, GL_RENDERBUFFER_OES, GL_FRAMEBUFFER_OES or GL_VERTEX_ARRAY_KHR",
                ),
            );
            return None;
        };
        let exists = match identifier {
            GL_BUFFER_KHR => self.is_buffer(name),
            GL_TEXTURE => self.is_texture(name),
            GL_RENDERBUFFER_OES => self.is_renderbuffer(name),
            GL_FRAMEBUFFER_OES => self.is_framebuffer(name),
            _ => self.is_vertex_array(name),
        };
        if !exists {
            self.bad_value(
                "name",
                name as i64,
                "name must be an existing object of the namespace identifier names (generated \
                 and bound at least once, not deleted)",
            );
            return None;
        }
        Some(kind)
    }

    /// Whether the namespace's labels live in the share group.
    fn shared_namespace(identifier: GLenum) -> bool {
        matches!(identifier, GL_BUFFER_KHR | GL_TEXTURE | GL_RENDERBUFFER_OES)
    }

    /// `glObjectLabelKHR`; `label` is `None` for a NULL label (which removes the label).
    pub fn object_label(
        &mut self,
        identifier: GLenum,
        name: GLuint,
        length: GLsizei,
        label: Option<&[u8]>,
    ) {
        if self.label_target(identifier, name).is_none() {
            return;
        }
        if let Some(l) = label {
            if l.len() >= MAX_LABEL_LENGTH {
                return self.bad_value(
                    if length < 0 {
                        "the length of label"
                    } else {
                        "length"
                    },
                    l.len() as i64,
                    "a label must be shorter than GL_MAX_LABEL_LENGTH_KHR (256)",
                );
            }
        }
        let label = label.map(|l| String::from_utf8_lossy(l).into_owned());
        self.set_label(identifier, name, label);
    }

    fn set_label(&mut self, identifier: GLenum, name: GLuint, label: Option<String>) {
        let key = (identifier, name);
        if Self::shared_namespace(identifier) {
            let shared = self.shared.clone();
            let mut o = lock_objects(&shared);
            match label {
                Some(l) => o.labels.insert(key, l),
                None => o.labels.remove(&key),
            };
        } else {
            match label {
                Some(l) => self.debug.labels.insert(key, l),
                None => self.debug.labels.remove(&key),
            };
        }
    }

    /// Forgets the labels of deleted objects.
    pub(super) fn forget_labels(&mut self, identifier: GLenum, names: &[GLuint]) {
        if names.is_empty() {
            return;
        }
        if Self::shared_namespace(identifier) {
            let shared = self.shared.clone();
            let mut o = lock_objects(&shared);
            if !o.labels.is_empty() {
                for &n in names {
                    o.labels.remove(&(identifier, n));
                }
            }
        } else {
            for &n in names {
                self.debug.labels.remove(&(identifier, n));
            }
        }
    }

    /// `glGetObjectLabelKHR`: the label (empty when there is none), or `None` after an error.
    pub fn object_label_of(
        &mut self,
        identifier: GLenum,
        name: GLuint,
        buf_size: GLsizei,
    ) -> Option<String> {
        if buf_size < 0 {
            self.bad_value("bufSize", buf_size as i64, "bufSize must not be negative");
            return None;
        }
        self.label_target(identifier, name)?;
        let key = (identifier, name);
        Some(if Self::shared_namespace(identifier) {
            let shared = self.shared.clone();
            let o = lock_objects(&shared);
            o.labels.get(&key).cloned().unwrap_or_default()
        } else {
            self.debug.labels.get(&key).cloned().unwrap_or_default()
        })
    }

    /// `glObjectPtrLabelKHR` and `glGetObjectPtrLabelKHR`: ES 1.1 has no sync objects, so
    /// no pointer names one.
    pub fn object_ptr_label(&mut self, ptr: usize, buf_size: Option<GLsizei>) {
        if let Some(b) = buf_size {
            if b < 0 {
                return self.bad_value("bufSize", b as i64, "bufSize must not be negative");
            }
        }
        self.bad_value(
            "ptr",
            ptr as i64,
            "ptr must be a sync object, and OpenGL ES 1.1 has none",
        );
    }

    /// `GL_DEBUG_OUTPUT_KHR` and `GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR` for `glEnable`,
    /// `glDisable` and `glIsEnabled`.
    pub(super) fn debug_flag(&mut self, cap: GLenum) -> Option<&mut bool> {
        match cap {
            GL_DEBUG_OUTPUT_KHR => Some(&mut self.debug.output),
            GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR => Some(&mut self.debug.synchronous),
            _ => None,
        }
    }

    /// The extension's state for `glGet`.
    pub(super) fn debug_value(&self, pname: GLenum) -> Option<super::get::Value> {
        use super::get::Value;
        let d = &self.debug;
        Some(match pname {
            GL_DEBUG_OUTPUT_KHR => Value::bools(&[d.output]),
            GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR => Value::bools(&[d.synchronous]),
            GL_MAX_DEBUG_MESSAGE_LENGTH_KHR => Value::int(MAX_DEBUG_MESSAGE_LENGTH as i64),
            GL_MAX_DEBUG_LOGGED_MESSAGES_KHR => Value::int(MAX_DEBUG_LOGGED_MESSAGES as i64),
            GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR => Value::int(MAX_DEBUG_GROUP_STACK_DEPTH as i64),
            GL_MAX_LABEL_LENGTH_KHR => Value::int(MAX_LABEL_LENGTH as i64),
            GL_DEBUG_LOGGED_MESSAGES_KHR => Value::int(d.logged() as i64),
            GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR => Value::int(d.next_length() as i64),
            GL_DEBUG_GROUP_STACK_DEPTH_KHR => Value::int(d.depth() as i64),
            _ => return None,
        })
    }

    /// `glGetPointervKHR`'s debug names: the callback and its parameter.
    pub fn debug_pointer(&self, pname: GLenum) -> Option<usize> {
        match pname {
            GL_DEBUG_CALLBACK_FUNCTION_KHR => Some(self.debug.callback.map_or(0, |f| f as usize)),
            GL_DEBUG_CALLBACK_USER_PARAM_KHR => Some(self.debug.user_param),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx() -> Context {
        let mut c = Context::new(None);
        c.call = "glTest";
        c.debug.output = true;
        c
    }

    #[test]
    fn errors_are_logged_in_words() {
        let mut c = ctx();
        c.call = "glEnable";
        c.set_capability(0x1234, true);
        assert_eq!(c.take_error(), GL_INVALID_ENUM);
        let m = c.debug_message_log(10, None);
        assert_eq!(m.len(), 1);
        assert_eq!(m[0].source, GL_DEBUG_SOURCE_API_KHR);
        assert_eq!(m[0].ty, GL_DEBUG_TYPE_ERROR_KHR);
        assert_eq!(m[0].id, GL_INVALID_ENUM);
        assert_eq!(m[0].severity, GL_DEBUG_SEVERITY_HIGH_KHR);
        assert!(m[0]
            .text
            .starts_with("glEnable: GL_INVALID_ENUM (0x0500): cap is 0x1234"));
    }

    #[test]
    fn disabled_output_formats_nothing() {
        let mut c = ctx();
        c.debug.output = false;
        c.set_error(GL_INVALID_VALUE);
        assert_eq!(c.debug.logged(), 0);
        assert_eq!(c.take_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn enum_names() {
        assert_eq!(
            EnumName(GL_TEXTURE_2D).to_string(),
            "0x0DE1 (GL_TEXTURE_2D)"
        );
        assert_eq!(
            EnumName(GL_DEBUG_OUTPUT_KHR).to_string(),
            "0x92E0 (GL_DEBUG_OUTPUT_KHR)"
        );
        assert!(EnumName(0xFFFF)
            .to_string()
            .starts_with("0xFFFF (not a token"));
    }

    #[test]
    fn control_by_ids_and_last_rule_wins() {
        let mut c = ctx();
        let (a, o, n) = (
            GL_DEBUG_SOURCE_APPLICATION_KHR,
            GL_DEBUG_TYPE_OTHER_KHR,
            GL_DEBUG_SEVERITY_NOTIFICATION_KHR,
        );
        assert!(c.debug.wants(a, o, 7, n));
        assert!(!c.debug.wants(a, o, 7, GL_DEBUG_SEVERITY_LOW_KHR));
        c.debug_message_control(a, o, GL_DONT_CARE, 1, &[7], false);
        assert!(!c.debug.wants(a, o, 7, n));
        assert!(c.debug.wants(a, o, 8, n));
        c.debug_message_control(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, &[], true);
        assert!(c.debug.wants(a, o, 7, GL_DEBUG_SEVERITY_LOW_KHR));
        assert_eq!(c.debug.groups[0].rules.len(), 1);
        c.debug_message_control(GL_DONT_CARE, o, GL_DONT_CARE, 1, &[7], false);
        assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn groups_restore_control_and_repeat_their_message() {
        let mut c = ctx();
        let a = GL_DEBUG_SOURCE_APPLICATION_KHR;
        c.push_debug_group(a, 5, -1, b"draw");
        c.debug_message_control(a, GL_DONT_CARE, GL_DONT_CARE, 0, &[], false);
        assert!(!c
            .debug
            .wants(a, GL_DEBUG_TYPE_OTHER_KHR, 1, GL_DEBUG_SEVERITY_HIGH_KHR));
        c.pop_debug_group();
        let m = c.debug_message_log(10, None);
        assert_eq!(m.len(), 2);
        assert_eq!(m[0].ty, GL_DEBUG_TYPE_PUSH_GROUP_KHR);
        assert_eq!(m[1].ty, GL_DEBUG_TYPE_POP_GROUP_KHR);
        assert_eq!((m[1].id, m[1].text.as_str()), (5, "draw"));
        c.pop_debug_group();
        assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    }

    #[test]
    fn log_is_bounded_and_fetch_stops_at_a_message_that_does_not_fit() {
        let mut c = ctx();
        for i in 0..(MAX_DEBUG_LOGGED_MESSAGES + 5) {
            let t = format!("m{i}");
            c.debug_message_insert(
                GL_DEBUG_SOURCE_APPLICATION_KHR,
                GL_DEBUG_TYPE_MARKER_KHR,
                i as u32,
                GL_DEBUG_SEVERITY_MEDIUM_KHR,
                -1,
                t.as_bytes(),
            );
        }
        assert_eq!(c.debug.logged(), MAX_DEBUG_LOGGED_MESSAGES);
        // "m0\0" and "m1\0" fit in 7 bytes, "m2\0" does not.
        let m = c.debug_message_log(10, Some(7));
        assert_eq!(m.len(), 2);
        assert_eq!(c.debug.next_length(), 3);
    }
}
