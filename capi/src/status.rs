//! Statuses, the thread-local error message, and the checks every entry point runs: panics
//! caught and turned into `SYMBODY_STATUS_PANIC`, pointers checked for null and alignment,
//! buffer lengths checked against what the call reads or writes.

use std::any::Any;
use std::cell::RefCell;
use std::ffi::{c_char, c_int, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// What a fallible function returns (as an `int`): 0 on success, one of the other values on
/// failure, with a message for `symbody_last_error_message()`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SymbodyStatus {
    /// Success.
    Ok = 0,
    /// A pointer argument was null (or misaligned for its type).
    NullPointer = 1,
    /// A buffer's length is shorter than what the call reads or writes; the message says
    /// how many entries it needs.
    BufferTooShort = 2,
    /// An argument is out of range: a formulation code, an index, a setting (α, step, time),
    /// a string that is not UTF-8, a formulation the mechanism was not generated in, or a
    /// joint that is not a driver.
    InvalidArgument = 3,
    /// No mechanism, joint or driver has that name; the message lists the known ones.
    UnknownName = 4,
    /// A solver failed (Newton did not converge, singular Jacobian, ...); the message has
    /// the time and the residual. A session stays at its last accepted step.
    Solver = 5,
    /// A bug inside the library was caught at the boundary; the message has the panic's.
    Panic = 6,
    /// No mechanism file can be read at the path: nothing is there, it is a folder, or it
    /// cannot be opened; the message names the path.
    FileNotFound = 7,
    /// The mechanism file was read but is no mechanism: not UTF-8 text, too large, a TOML
    /// error or a modelling error; the message names the file and gives the diagnostics with
    /// their line:column.
    InvalidFile = 8,
}

/// Which dynamics formulation a mechanism or session uses (the `formulation` arguments
/// take these values as an `int`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SymbodyFormulation {
    /// The mechanism's first generated formulation.
    Default = 0,
    /// The paper's: constant diagonal mass matrix against Euler-angle accelerations.
    Paper = 1,
    /// Mass matrix and velocity-dependent forces from the exact kinetic energy.
    Exact = 2,
}

/// A failed call: its status and message.
#[derive(Debug)]
pub(crate) struct Failure {
    pub status: SymbodyStatus,
    pub message: String,
}

impl Failure {
    pub fn new(status: SymbodyStatus, message: impl Into<String>) -> Failure {
        Failure {
            status,
            message: message.into(),
        }
    }

    fn from_panic(payload: Box<dyn Any + Send>) -> Failure {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic without a message".to_string());
        Failure::new(
            SymbodyStatus::Panic,
            format!("internal error (a bug in symbody, please report it): {what}"),
        )
    }

    /// Stores the message as this thread's last error and returns the status as an `int`.
    fn record(self) -> c_int {
        set_last_error(&self.message);
        self.status as c_int
    }
}

/// A solver or setting error of the runtime, classified.
impl From<symbody_runtime::Error> for Failure {
    fn from(e: symbody_runtime::Error) -> Failure {
        use symbody_runtime::Error as E;
        let status = match e {
            E::InvalidSetting { .. } | E::DimensionMismatch { .. } | E::InvalidIndex { .. } => {
                SymbodyStatus::InvalidArgument
            }
            _ => SymbodyStatus::Solver,
        };
        Failure::new(status, e.to_string())
    }
}

impl Failure {
    /// An error of `symbody::session`; `options` is the status its option errors (bad
    /// names) get in the calling context.
    pub fn from_session(e: symbody::session::Error, options: SymbodyStatus) -> Failure {
        use symbody::scenario::ScenarioError as E;
        match e {
            E::Runtime(e) => e.into(),
            E::Options(s) => Failure::new(options, s),
            E::Layout(s) => Failure::new(SymbodyStatus::InvalidArgument, s),
            // A session neither writes files nor watches for interrupts.
            e @ (E::Interrupted { .. } | E::Output(_)) => {
                Failure::new(SymbodyStatus::Solver, e.to_string())
            }
        }
    }
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last_error(message: &str) {
    let c = CString::new(message.replace('\0', "\u{FFFD}")).unwrap_or_default();
    // Fails only while the thread is being torn down, when nobody can read it anyway.
    let _ = LAST_ERROR.try_with(|m| *m.borrow_mut() = c);
}

/// Runs an entry point's body: its error, or a panic inside it, becomes a nonzero status and
/// this thread's last error message.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), Failure>) -> c_int {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => SymbodyStatus::Ok as c_int,
        Ok(Err(f)) => f.record(),
        Err(payload) => Failure::from_panic(payload).record(),
    }
}

/// [`guard`] for the functions that return a value instead of a status: on failure the
/// message is recorded and `fallback` returned.
pub(crate) fn guard_value<T>(fallback: T, body: impl FnOnce() -> Result<T, Failure>) -> T {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(v)) => v,
        Ok(Err(f)) => {
            f.record();
            fallback
        }
        Err(payload) => {
            Failure::from_panic(payload).record();
            fallback
        }
    }
}

fn null(what: &str) -> Failure {
    Failure::new(
        SymbodyStatus::NullPointer,
        format!("`{what}` is a null or misaligned pointer"),
    )
}

/// `p` as a shared reference, or a `NullPointer` failure naming the argument.
///
/// # Safety
/// A non-null, aligned `p` points to a live `T` not mutated during `'a`.
pub(crate) unsafe fn arg<'a, T>(p: *const T, what: &str) -> Result<&'a T, Failure> {
    if p.is_null() || !p.is_aligned() {
        return Err(null(what));
    }
    // SAFETY: non-null and aligned; validity is the caller's contract.
    Ok(unsafe { &*p })
}

/// `p` as an exclusive reference, or a `NullPointer` failure naming the argument.
///
/// # Safety
/// A non-null, aligned `p` points to a live `T` not accessed elsewhere during `'a`.
pub(crate) unsafe fn arg_mut<'a, T>(p: *mut T, what: &str) -> Result<&'a mut T, Failure> {
    if p.is_null() || !p.is_aligned() {
        return Err(null(what));
    }
    // SAFETY: non-null and aligned; validity is the caller's contract.
    Ok(unsafe { &mut *p })
}

fn too_short(what: &str, len: usize, need: usize) -> Failure {
    Failure::new(
        SymbodyStatus::BufferTooShort,
        format!("`{what}` has length {len}; this call needs {need}"),
    )
}

/// The first `need` entries of the caller's buffer `(p, len)`, checked.
///
/// # Safety
/// A non-null `p` points to `len` readable values not mutated during `'a`.
pub(crate) unsafe fn input<'a, T>(
    p: *const T,
    len: usize,
    need: usize,
    what: &str,
) -> Result<&'a [T], Failure> {
    if p.is_null() || !p.is_aligned() {
        return Err(null(what));
    }
    if len < need {
        return Err(too_short(what, len, need));
    }
    // SAFETY: checked above; the caller vouches for `len >= need` readable values.
    Ok(unsafe { std::slice::from_raw_parts(p, need) })
}

/// The first `need` entries of the caller's output buffer `(p, len)`, checked.
///
/// # Safety
/// A non-null `p` points to `len` writable values not accessed elsewhere during `'a`.
pub(crate) unsafe fn output<'a, T>(
    p: *mut T,
    len: usize,
    need: usize,
    what: &str,
) -> Result<&'a mut [T], Failure> {
    if p.is_null() || !p.is_aligned() {
        return Err(null(what));
    }
    if len < need {
        return Err(too_short(what, len, need));
    }
    // SAFETY: checked above; the caller vouches for `len >= need` writable values.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, need) })
}

/// The caller's NUL-terminated string as UTF-8.
///
/// # Safety
/// A non-null `p` points to a NUL-terminated string that stays unchanged during `'a`.
pub(crate) unsafe fn string<'a>(p: *const c_char, what: &str) -> Result<&'a str, Failure> {
    if p.is_null() {
        return Err(null(what));
    }
    // SAFETY: non-null; NUL termination is the caller's contract.
    let s = unsafe { CStr::from_ptr(p) };
    s.to_str().map_err(|_| {
        Failure::new(
            SymbodyStatus::InvalidArgument,
            format!("`{what}` is not valid UTF-8"),
        )
    })
}

/// The message of the last failed call on this thread, NUL-terminated (empty if no call on
/// this thread has failed). Successful calls leave it unchanged. The pointer is owned by the
/// library and valid until the next call into the library on this thread; copy the text to
/// keep it.
#[no_mangle]
pub extern "C" fn symbody_last_error_message() -> *const c_char {
    static EMPTY: &CStr = c"";
    LAST_ERROR
        .try_with(|m| m.borrow().as_ptr())
        .unwrap_or(EMPTY.as_ptr())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn last() -> String {
        // SAFETY: the library's own NUL-terminated string, read before the next call.
        unsafe { CStr::from_ptr(symbody_last_error_message()) }
            .to_str()
            .unwrap()
            .to_string()
    }

    #[test]
    fn a_panic_becomes_a_status_and_a_message() {
        let status = guard(|| panic!("boom {}", 42));
        assert_eq!(status, SymbodyStatus::Panic as c_int);
        assert!(last().contains("boom 42"), "{}", last());
        let v = guard_value(-1.0, || -> Result<f64, Failure> { panic!("static boom") });
        assert_eq!(v, -1.0);
        assert!(last().contains("static boom"), "{}", last());
    }

    #[test]
    fn success_leaves_the_last_message_alone() {
        guard(|| Err(Failure::new(SymbodyStatus::InvalidArgument, "first")));
        assert_eq!(guard(|| Ok(())), 0);
        assert_eq!(last(), "first");
    }

    #[test]
    fn a_nul_inside_a_message_does_not_lose_it() {
        guard(|| Err(Failure::new(SymbodyStatus::InvalidArgument, "a\0b")));
        assert_eq!(last(), "a\u{FFFD}b");
    }
}
