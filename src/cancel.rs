//! Cancelling a run from outside: a [`Token`] that another thread sets, and the checkpoints of
//! the solver loops that honour it.
//!
//! A caller that wants to stop a run (the Python module on Ctrl-C) creates a [`Token`], runs the
//! work inside [`Token::run`] and sets the token from another thread ([`Token::cancel`]). The
//! solver's iteration loops (each Newton step, each hundred Gauss–Seidel sweeps) and the
//! solve's entry call [`checkpoint`]: when the token of the current thread is set, it unwinds
//! the stack with the payload [`Cancelled`], which [`Token::run`] turns into `Err(Cancelled)`.
//! Everything on the way is dropped as for an error (an output folder's lock and temporary
//! folder are removed; nothing is written). Without a token, as in the `rollbem` program, a
//! checkpoint is one thread-local read.
//!
//! The token belongs to the thread that runs [`Token::run`]: work that fans out to other
//! threads (the runs of a sweep) calls [`Token::run`] with the same token on each.
//!
//! **Scope.** Nothing here is process-wide: each call makes its own token (its flag shared only
//! with the thread that may set it), [`Token::run`] installs it for the duration of its work on
//! its thread and restores the previous one after, and a checkpoint never changes what a run
//! computes, only whether it goes on. The thread-local spares the solver's signatures a
//! parameter that only a cancelling caller uses; a run context passed down to the solver (the
//! Newton workspace would carry it) is the explicit alternative, not built.

use std::cell::RefCell;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// A request to stop, shared by the thread that asks and the threads that work.
#[derive(Debug, Clone, Default)]
pub struct Token(Arc<AtomicBool>);

/// The payload a cancelled run unwinds with, and the error [`Token::run`] returns for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cancelled;

impl std::fmt::Display for Cancelled {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("the run was cancelled")
    }
}

impl std::error::Error for Cancelled {}

thread_local! {
    /// The token of the work running on this thread, if any.
    static CURRENT: RefCell<Option<Token>> = const { RefCell::new(None) };
}

impl Token {
    /// A token not (yet) set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks the work running under this token to stop at its next checkpoint.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::SeqCst);
    }

    /// Whether [`Token::cancel`] was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }

    /// Runs `work` on this thread under this token: `Err(Cancelled)` when a checkpoint found the
    /// token set (or it was set before `work` began). A panic of `work` passes on unchanged.
    pub fn run<T>(&self, work: impl FnOnce() -> T) -> Result<T, Cancelled> {
        if self.is_cancelled() {
            return Err(Cancelled);
        }
        let previous = CURRENT.with(|c| c.replace(Some(self.clone())));
        let outcome = catch_unwind(AssertUnwindSafe(work));
        CURRENT.with(|c| *c.borrow_mut() = previous);
        match outcome {
            Ok(value) => Ok(value),
            Err(payload) if payload.is::<Cancelled>() => Err(Cancelled),
            Err(payload) => resume_unwind(payload),
        }
    }
}

/// Stops the current work (unwinding to its [`Token::run`] with [`Cancelled`]) when its token
/// is set; returns at once otherwise, and always on a thread without a token.
pub fn checkpoint() {
    let cancelled = CURRENT.with(|c| c.borrow().as_ref().is_some_and(Token::is_cancelled));
    if cancelled {
        // resume_unwind: no panic hook runs, so nothing is reported as a bug.
        resume_unwind(Box::new(Cancelled));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_set_token_stops_at_the_next_checkpoint() {
        let token = Token::new();
        let mut reached = 0;
        let outcome = token.run(|| {
            for k in 0..10 {
                checkpoint();
                reached = k;
                if k == 3 {
                    token.cancel();
                }
            }
        });
        assert_eq!(outcome, Err(Cancelled));
        assert_eq!(reached, 3);
        // The thread has no token afterwards: checkpoints return.
        checkpoint();
        assert_eq!(token.run(|| 1), Err(Cancelled));
        assert_eq!(Token::new().run(|| 1), Ok(1));
    }

    #[test]
    fn a_solve_stops_soon_after_the_token_is_set() {
        // About 10 s uncancelled (half a second a Newton step); cancelled 0.5 s in.
        let token = Token::new();
        let setter = token.clone();
        let cancel = std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_millis(500));
            setter.cancel();
        });
        let start = std::time::Instant::now();
        let outcome = token.run(|| {
            crate::app::solve_case(
                std::path::Path::new("cases/carter_051.yaml"),
                &["contact.grid.elements=701"],
            )
            .map(|s| s.report.iterations)
        });
        cancel.join().unwrap();
        assert!(matches!(outcome, Err(Cancelled)), "not cancelled");
        assert!(start.elapsed().as_secs_f64() < 4.0, "{:?}", start.elapsed());
    }

    #[test]
    fn other_panics_pass_through() {
        let caught = catch_unwind(|| Token::new().run(|| panic!("a bug")));
        assert!(caught.is_err());
        checkpoint();
    }
}
