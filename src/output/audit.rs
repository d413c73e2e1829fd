//! The last check before a report leaves the program: every number it holds
//! is finite where a finite one is meant.
//!
//! A report marks the numbers that may be infinite or NaN by writing them
//! through [`float_or_inf`](super::report::float_or_inf) (a gap of `inf`,
//! the ductility of an elastic storey, the dispersion of fewer than two
//! values): those reach a human-readable serializer as the strings `inf`,
//! `-inf` or `nan`. Every other float is a measured quantity (a peak, an
//! energy, a time), and a non-finite one there is a run that went wrong
//! (an overflow, 0/0), not a result. [`first_non_finite`] walks a report
//! through its `Serialize`, the same walk every output format takes, and
//! names the first such quantity by its path in the JSON form
//! (`buildings[0].floors[2].peak_absolute_acceleration`).

use std::fmt;

use serde::Serialize;
use serde::ser::{self, Impossible};

/// A quantity that should be finite and is not: where, and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct NonFinite {
    /// The path in the report's JSON form.
    pub path: String,
    pub value: f64,
}

impl fmt::Display for NonFinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the result holds a non-finite number, {} = {}: the run went wrong, so nothing is reported",
            self.path,
            super::Num(self.value)
        )
    }
}

/// The first quantity of `report` that should be finite and is not.
pub fn first_non_finite<T: Serialize + ?Sized>(report: &T) -> Option<NonFinite> {
    let mut walker = Walker::default();
    match report.serialize(&mut walker) {
        Err(Stop::Found(found)) => Some(found),
        // A report that does not serialize fails in its writer, with its
        // own message.
        Ok(()) | Err(Stop::Other(_)) => None,
    }
}

/// Where the walk is: one segment per struct field, sequence element or map key.
#[derive(Default)]
struct Walker {
    path: Vec<String>,
    /// The next index of each sequence being walked, innermost last.
    indices: Vec<usize>,
}

impl Walker {
    fn path(&self) -> String {
        let mut out = String::new();
        for segment in &self.path {
            if !out.is_empty() && !segment.starts_with('[') {
                out.push('.');
            }
            out.push_str(segment);
        }
        if out.is_empty() {
            "the report".into()
        } else {
            out
        }
    }

    fn begin_sequence(&mut self) -> &mut Self {
        self.indices.push(0);
        self
    }

    fn element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        let i = self.indices.last_mut().expect("inside a sequence");
        self.path.push(format!("[{i}]"));
        *i += 1;
        let out = value.serialize(&mut *self);
        self.path.pop();
        out
    }

    fn end_sequence(&mut self) -> Result<(), Stop> {
        self.indices.pop();
        Ok(())
    }

    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Stop> {
        self.path.push(key.to_string());
        let out = value.serialize(&mut *self);
        self.path.pop();
        out
    }
}

/// Why the walk stopped.
#[derive(Debug)]
enum Stop {
    Found(NonFinite),
    Other(String),
}

impl fmt::Display for Stop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stop::Found(n) => n.fmt(f),
            Stop::Other(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Stop {}

impl ser::Error for Stop {
    fn custom<M: fmt::Display>(message: M) -> Self {
        Stop::Other(message.to_string())
    }
}

/// Leaves that hold no float.
macro_rules! ignore {
    ($($method:ident: $t:ty),* $(,)?) => {
        $(fn $method(self, _: $t) -> Result<(), Stop> { Ok(()) })*
    };
}

impl ser::Serializer for &mut Walker {
    type Ok = ();
    type Error = Stop;
    type SerializeSeq = Self;
    type SerializeTuple = Self;
    type SerializeTupleStruct = Self;
    type SerializeTupleVariant = Self;
    type SerializeMap = Self;
    type SerializeStruct = Self;
    type SerializeStructVariant = Self;

    /// As the JSON writer: [`float_or_inf`](super::report::float_or_inf)
    /// writes its non-finite values as text then.
    fn is_human_readable(&self) -> bool {
        true
    }

    fn serialize_f64(self, v: f64) -> Result<(), Stop> {
        if v.is_finite() {
            Ok(())
        } else {
            Err(Stop::Found(NonFinite {
                path: self.path(),
                value: v,
            }))
        }
    }

    fn serialize_f32(self, v: f32) -> Result<(), Stop> {
        self.serialize_f64(f64::from(v))
    }

    ignore!(
        serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8],
        serialize_unit_struct: &'static str,
    );

    fn serialize_none(self) -> Result<(), Stop> {
        Ok(())
    }

    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Stop> {
        value.serialize(self)
    }

    fn serialize_unit(self) -> Result<(), Stop> {
        Ok(())
    }

    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Stop> {
        Ok(())
    }

    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Stop> {
        value.serialize(self)
    }

    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Stop> {
        self.field(variant, value)
    }

    fn serialize_seq(self, _: Option<usize>) -> Result<Self, Stop> {
        Ok(self.begin_sequence())
    }

    fn serialize_tuple(self, _: usize) -> Result<Self, Stop> {
        Ok(self.begin_sequence())
    }

    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Self, Stop> {
        Ok(self.begin_sequence())
    }

    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Self, Stop> {
        self.path.push(variant.to_string());
        Ok(self.begin_sequence())
    }

    fn serialize_map(self, _: Option<usize>) -> Result<Self, Stop> {
        self.path.push(String::new());
        Ok(self)
    }

    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, Stop> {
        Ok(self)
    }

    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        _: usize,
    ) -> Result<Self, Stop> {
        self.path.push(variant.to_string());
        Ok(self)
    }
}

/// The sequence-like forms: each element one index deeper; a tuple
/// variant's name was pushed when it began.
macro_rules! sequence {
    ($($trait:ident :: $method:ident, pops_variant: $pops:expr;)*) => {$(
        impl ser::$trait for &mut Walker {
            type Ok = ();
            type Error = Stop;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
                self.element(value)
            }
            fn end(self) -> Result<(), Stop> {
                if $pops {
                    self.path.pop();
                }
                self.end_sequence()
            }
        }
    )*};
}

sequence! {
    SerializeSeq::serialize_element, pops_variant: false;
    SerializeTuple::serialize_element, pops_variant: false;
    SerializeTupleStruct::serialize_field, pops_variant: false;
    SerializeTupleVariant::serialize_field, pops_variant: true;
}

impl ser::SerializeMap for &mut Walker {
    type Ok = ();
    type Error = Stop;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), Stop> {
        // The key as its JSON text, unquoted: map keys are names or numbers.
        let name = key.serialize(KeyName).unwrap_or_else(|_| "?".into());
        *self.path.last_mut().expect("inside a map") = name;
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Stop> {
        value.serialize(&mut **self)
    }
    fn end(self) -> Result<(), Stop> {
        self.path.pop();
        Ok(())
    }
}

/// The struct forms: each field one name deeper; a struct variant's name
/// was pushed when it began.
macro_rules! structure {
    ($($trait:ident, pops_variant: $pops:expr;)*) => {$(
        impl ser::$trait for &mut Walker {
            type Ok = ();
            type Error = Stop;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), Stop> {
                self.field(key, value)
            }
            fn end(self) -> Result<(), Stop> {
                if $pops {
                    self.path.pop();
                }
                Ok(())
            }
        }
    )*};
}

structure! {
    SerializeStruct, pops_variant: false;
    SerializeStructVariant, pops_variant: true;
}

/// A map key as text: a string or a number; anything else is not a name.
struct KeyName;

macro_rules! key_number {
    ($($method:ident: $t:ty),* $(,)?) => {
        $(fn $method(self, v: $t) -> Result<String, Stop> { Ok(v.to_string()) })*
    };
}

macro_rules! not_a_key {
    ($($method:ident: $t:ty),* $(,)?) => {
        $(fn $method(self, _: $t) -> Result<String, Stop> { Err(Stop::Other("key".into())) })*
    };
}

impl ser::Serializer for KeyName {
    type Ok = String;
    type Error = Stop;
    type SerializeSeq = Impossible<String, Stop>;
    type SerializeTuple = Impossible<String, Stop>;
    type SerializeTupleStruct = Impossible<String, Stop>;
    type SerializeTupleVariant = Impossible<String, Stop>;
    type SerializeMap = Impossible<String, Stop>;
    type SerializeStruct = Impossible<String, Stop>;
    type SerializeStructVariant = Impossible<String, Stop>;

    key_number!(
        serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_f32: f32, serialize_f64: f64, serialize_char: char,
        serialize_str: &str,
    );
    not_a_key!(serialize_bytes: &[u8], serialize_unit_struct: &'static str);

    fn serialize_none(self) -> Result<String, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<String, Stop> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<String, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<String, Stop> {
        Ok(variant.to_string())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<String, Stop> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<String, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_tuple_struct(
        self,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleStruct, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeTupleVariant, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self::SerializeStruct, Stop> {
        Err(Stop::Other("key".into()))
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, Stop> {
        Err(Stop::Other("key".into()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::report::float_or_inf;
    use std::collections::BTreeMap;

    #[derive(Serialize)]
    struct Floor {
        peak: f64,
        #[serde(serialize_with = "float_or_inf")]
        ductility: f64,
    }

    #[derive(Serialize)]
    struct Building {
        name: String,
        floors: Vec<Floor>,
        energy: Option<(f64, f64)>,
        by_name: BTreeMap<String, f64>,
    }

    fn building() -> Building {
        Building {
            name: "block".into(),
            floors: vec![
                Floor {
                    peak: 0.1,
                    ductility: f64::INFINITY,
                },
                Floor {
                    peak: 0.2,
                    ductility: f64::NAN,
                },
            ],
            energy: Some((1.0, 2.0)),
            by_name: BTreeMap::from([("a".into(), 1.0), ("b".into(), 2.0)]),
        }
    }

    #[test]
    fn values_marked_as_possibly_infinite_pass() {
        assert_eq!(first_non_finite(&building()), None);
        assert_eq!(first_non_finite(&vec![building()]), None);
    }

    #[test]
    fn a_measured_quantity_that_is_not_finite_is_named_by_its_path() {
        let mut b = building();
        b.floors[1].peak = f64::NAN;
        let found = first_non_finite(&vec![building(), b]).unwrap();
        assert_eq!(found.path, "[1].floors[1].peak");
        assert!(found.value.is_nan());
        let mut b = building();
        b.energy = Some((1.0, f64::NEG_INFINITY));
        assert_eq!(
            first_non_finite(&b).unwrap().to_string(),
            "the result holds a non-finite number, energy[1] = -inf: the run went wrong, so nothing is reported"
        );
        let mut b = building();
        b.by_name.insert("b".into(), f64::INFINITY);
        assert_eq!(first_non_finite(&b).unwrap().path, "by_name.b");
    }
}
