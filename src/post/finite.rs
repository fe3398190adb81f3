//! The last guard before anything is written: every number of a solved case must be finite.
//!
//! Validation keeps the inputs and the derived scales in range, so a NaN or an infinity here
//! means the numerics broke down (a singular system, an overflow in a kernel). Such a run ends
//! with [`Error::NotFinite`] (exit code 2, like a run that did not converge) and writes nothing,
//! rather than a summary.json whose NaN turned into `null` or a CSV full of `NaN`.
//!
//! [`first_non_finite`] walks any `Serialize` value (the summary, the contact solution) and names
//! the first number that is not finite by its path, e.g. `solver.history[3].residual`.

use crate::error::Error;
use serde::ser::{self, Serialize};
use std::fmt::Display;
use std::path::Path;

/// Path and value of the first non-finite number in `value`, if any.
pub fn first_non_finite<T: Serialize + ?Sized>(value: &T) -> Option<(String, f64)> {
    let mut walker = Walker::default();
    // The walker never fails: errors are only its way of stopping early.
    let _ = value.serialize(&mut walker);
    walker.found
}

/// [`Error::NotFinite`] for `case` if `value` holds a non-finite number; `what` names the value
/// ("the contact solution", "summary.json").
pub fn check<T: Serialize + ?Sized>(case: &Path, what: &str, value: &T) -> Result<(), Error> {
    match first_non_finite(value) {
        None => Ok(()),
        Some((path, v)) => Err(not_finite(case, &format!("{what}: `{path}`"), v)),
    }
}

/// [`Error::NotFinite`] for the first non-finite number of `values`, named `what[i]`.
pub fn check_values<'a>(case: &Path, what: &str, values: impl IntoIterator<Item = &'a f64>) -> Result<(), Error> {
    match values.into_iter().enumerate().find(|(_, v)| !v.is_finite()) {
        None => Ok(()),
        Some((i, v)) => Err(not_finite(case, &format!("{what}[{i}]"), *v)),
    }
}

/// Checks the post-processed fields: the interior grid and the boundary fields of `bem` bodies.
pub fn check_fields(
    case: &Path,
    interior: Option<&crate::interior::InteriorField>,
    boundary: &[Option<crate::body::BoundaryField>; 2],
) -> Result<(), Error> {
    if let Some(f) = interior {
        check_values(case, "interior stress", f.stress.iter().flatten())?;
        check_values(case, "interior displacement", f.displacement.iter().flatten())?;
    }
    for (side, field) in ["A", "B"].iter().zip(boundary) {
        if let Some(f) = field {
            check_values(
                case,
                &format!("boundary displacement of {side}"),
                f.displacement.iter().flatten(),
            )?;
            check_values(
                case,
                &format!("boundary traction of {side}"),
                f.traction.iter().flatten(),
            )?;
        }
    }
    Ok(())
}

fn not_finite(case: &Path, what: &str, value: f64) -> Error {
    Error::NotFinite {
        case: case.to_path_buf(),
        what: what.to_string(),
        value,
    }
}

/// A serializer that records where the first non-finite float is and otherwise does nothing.
#[derive(Default)]
struct Walker {
    path: Vec<Part>,
    found: Option<(String, f64)>,
}

/// One step of the path to a number: an index or a key. Built for every element walked, so
/// only a map's key (rare in rollbem's outputs) allocates; the text is made when a number fails.
enum Part {
    Index(usize),
    Name(&'static str),
    Key(String),
}

/// Stops the walk (never shown to the user).
#[derive(Debug)]
struct Stop;

impl Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("stop")
    }
}

impl std::error::Error for Stop {}

impl ser::Error for Stop {
    fn custom<M: Display>(_: M) -> Self {
        Stop
    }
}

impl Walker {
    fn number(&mut self, v: f64) -> Result<(), Stop> {
        if v.is_finite() {
            return Ok(());
        }
        let mut path = String::new();
        for part in &self.path {
            match part {
                Part::Index(i) => path.push_str(&format!("[{i}]")),
                Part::Name(name) => push_name(&mut path, name),
                Part::Key(name) => push_name(&mut path, name),
            }
        }
        self.found = Some((if path.is_empty() { "(value)".into() } else { path }, v));
        Err(Stop)
    }

    fn within<T: Serialize + ?Sized>(&mut self, part: Part, value: &T) -> Result<(), Stop> {
        self.path.push(part);
        let result = value.serialize(&mut *self);
        self.path.pop();
        result
    }
}

/// `name` appended to a dotted path.
fn push_name(path: &mut String, name: &str) {
    if !path.is_empty() {
        path.push('.');
    }
    path.push_str(name);
}

/// Sequences, maps and structs: each element under its index or key.
struct Compound<'a> {
    walker: &'a mut Walker,
    index: usize,
    key: Option<Part>,
}

/// Serializer methods for values that hold no floating-point number: nothing to check.
macro_rules! ignore {
    ($($method:ident($($arg:ty),*)),* $(,)?) => {$(
        fn $method(self, $(_: $arg),*) -> Result<(), Stop> {
            Ok(())
        }
    )*};
}

/// Serializer methods that open a compound of `len` parts: all walked like a sequence.
macro_rules! compound {
    ($($method:ident($($arg:ty),*)),* $(,)?) => {$(
        fn $method(self, $(_: $arg,)* len: usize) -> Result<Compound<'a>, Stop> {
            self.serialize_seq(Some(len))
        }
    )*};
}

impl<'a> ser::Serializer for &'a mut Walker {
    type Ok = ();
    type Error = Stop;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    ignore!(
        serialize_none(),
        serialize_unit(),
        serialize_bool(bool),
        serialize_i8(i8),
        serialize_i16(i16),
        serialize_i32(i32),
        serialize_i64(i64),
        serialize_u8(u8),
        serialize_u16(u16),
        serialize_u32(u32),
        serialize_u64(u64),
        serialize_char(char),
        serialize_str(&str),
        serialize_bytes(&[u8]),
        serialize_unit_struct(&'static str),
        serialize_unit_variant(&'static str, u32, &'static str),
    );
    fn serialize_f32(self, v: f32) -> Result<(), Stop> {
        self.number(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Stop> {
        self.number(v)
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Stop> {
        value.serialize(self)
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, value: &T) -> Result<(), Stop> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Stop> {
        self.within(Part::Name(variant), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Stop> {
        Ok(Compound {
            walker: self,
            index: 0,
            key: None,
        })
    }
    compound!(
        serialize_tuple(),
        serialize_tuple_struct(&'static str),
        serialize_tuple_variant(&'static str, u32, &'static str),
        serialize_struct(&'static str),
        serialize_struct_variant(&'static str, u32, &'static str),
    );
    fn serialize_map(self, len: Option<usize>) -> Result<Compound<'a>, Stop> {
        self.serialize_seq(len)
    }
}

impl Compound<'_> {
    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        let part = Part::Index(self.index);
        self.index += 1;
        self.walker.within(part, value)
    }
}

/// The compound serializers whose parts are found by position.
macro_rules! positional {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
                self.element(value)
            }
            fn end(self) -> Result<(), Stop> {
                Ok(())
            }
        }
    )*};
}
positional!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Stop;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Stop> {
        // Keys are names (strings) in every output of rollbem; others are shown by position.
        self.key = Some(
            serde_json::to_value(key)
                .ok()
                .and_then(|k| k.as_str().map(|k| Part::Key(k.to_string())))
                .unwrap_or(Part::Index(self.index)),
        );
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        let key = self.key.take().unwrap_or(Part::Index(self.index));
        self.index += 1;
        self.walker.within(key, value)
    }
    fn end(self) -> Result<(), Stop> {
        Ok(())
    }
}

/// The compound serializers whose parts are found by field name.
macro_rules! named {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Stop;
            fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, value: &T) -> Result<(), Stop> {
                self.walker.within(Part::Name(key), value)
            }
            fn end(self) -> Result<(), Stop> {
                Ok(())
            }
        }
    )*};
}
named!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(serde::Serialize)]
    struct Record {
        iteration: usize,
        residual: f64,
        note: Option<f64>,
    }

    #[derive(serde::Serialize)]
    struct Report {
        converged: bool,
        history: Vec<Record>,
        zones: Vec<[f64; 2]>,
        by_name: BTreeMap<String, f64>,
    }

    fn report() -> Report {
        Report {
            converged: true,
            history: (0..3)
                .map(|i| Record {
                    iteration: i,
                    residual: 10f64.powi(-(i as i32)),
                    note: None,
                })
                .collect(),
            zones: vec![[-1.0, 0.5], [0.5, 1.0]],
            by_name: [("a".to_string(), 1.0)].into_iter().collect(),
        }
    }

    #[test]
    fn finite_values_pass_and_none_is_not_a_number() {
        assert_eq!(first_non_finite(&report()), None);
    }

    #[test]
    fn the_first_non_finite_number_is_named_by_its_path() {
        let mut r = report();
        r.history[2].residual = f64::NAN;
        let (path, v) = first_non_finite(&r).unwrap();
        assert_eq!(path, "history[2].residual");
        assert!(v.is_nan());

        let mut r = report();
        r.zones[1][0] = f64::INFINITY;
        assert_eq!(first_non_finite(&r).unwrap().0, "zones[1][0]");

        let mut r = report();
        r.history[0].note = Some(f64::NEG_INFINITY);
        assert_eq!(first_non_finite(&r).unwrap().0, "history[0].note");

        let mut r = report();
        r.by_name.insert("b".into(), f64::NAN);
        assert_eq!(first_non_finite(&r).unwrap().0, "by_name.b");
    }

    #[test]
    fn check_turns_a_nan_into_the_exit_code_of_a_failed_solve() {
        let mut r = report();
        r.history[1].residual = f64::NAN;
        let err = check(Path::new("case.yaml"), "summary.json", &r).unwrap_err();
        assert_eq!(err.exit_code(), crate::error::EXIT_NOT_CONVERGED);
        let text = err.to_string();
        assert!(
            text.contains("case.yaml") && text.contains("history[1].residual"),
            "{text}"
        );
        let err = check_values(Path::new("c.yaml"), "pressure", &[1.0, f64::NAN]).unwrap_err();
        assert!(err.to_string().contains("pressure[1]"), "{err}");
    }
}
