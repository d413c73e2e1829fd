//! The JSON's lists of points, cells and records as numpy arrays: a list
//! of objects with the same keys becomes one object of columns, a column
//! of numbers a numpy array (JSON's `"inf"`, `"-inf"` and `"nan"` and a
//! missing `null` read as the floats they stand for), a column of objects
//! an object of columns, and any other column a list.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// The columns of `rows`, a list of dicts with the same keys (the first
/// row's); `shape` reshapes every numeric column (a map's grid).
pub fn columns<'py>(
    rows: &Bound<'py, PyList>,
    shape: Option<[usize; 2]>,
) -> PyResult<Bound<'py, PyDict>> {
    let py = rows.py();
    let out = PyDict::new(py);
    let Some(first) = rows.iter().next() else {
        return Ok(out);
    };
    let first = first.cast_into::<PyDict>()?;
    for key in first.keys() {
        let column: Vec<Bound<'py, PyAny>> = rows
            .iter()
            .map(|row| {
                row.cast::<PyDict>()?
                    .get_item(&key)
                    .map(|v| v.unwrap_or_else(|| py.None().into_bound(py)))
            })
            .collect::<PyResult<_>>()?;
        out.set_item(key, column_value(py, column, shape)?)?;
    }
    Ok(out)
}

fn column_value<'py>(
    py: Python<'py>,
    column: Vec<Bound<'py, PyAny>>,
    shape: Option<[usize; 2]>,
) -> PyResult<Bound<'py, PyAny>> {
    if column.iter().all(|v| v.is_instance_of::<PyDict>()) {
        return Ok(columns(&PyList::new(py, column)?, shape)?.into_any());
    }
    let reshape = |a: Bound<'py, PyAny>| match shape {
        Some(s) => a.call_method1("reshape", (s,)),
        None => Ok(a),
    };
    if column.iter().all(|v| v.is_instance_of::<PyBool>()) {
        let values: Vec<bool> = column
            .iter()
            .map(|v| v.is_truthy())
            .collect::<PyResult<_>>()?;
        return reshape(PyArray1::from_vec(py, values).into_any());
    }
    let ints = column
        .iter()
        .all(|v| v.is_instance_of::<PyInt>() && !v.is_instance_of::<PyBool>());
    if ints
        && let Ok(values) = column
            .iter()
            .map(|v| v.extract::<i64>())
            .collect::<PyResult<Vec<_>>>()
    {
        return reshape(PyArray1::from_vec(py, values).into_any());
    }
    if let Some(values) = column.iter().map(float).collect::<Option<Vec<f64>>>() {
        // All missing is no column of numbers.
        if !column.iter().all(|v| v.is_none()) {
            let array = PyArray1::from_vec(py, values);
            return reshape(array.into_any());
        }
    }
    Ok(PyList::new(py, column)?.into_any())
}

/// A JSON number as a float: `"inf"`, `"-inf"` and `"nan"` (how the JSON
/// writes what it has no number for) and a missing value (`None`: NaN)
/// included; `None` for anything else.
fn float(v: &Bound<'_, PyAny>) -> Option<f64> {
    if v.is_none() {
        return Some(f64::NAN);
    }
    if v.is_instance_of::<PyFloat>()
        || (v.is_instance_of::<PyInt>() && !v.is_instance_of::<PyBool>())
    {
        return v.extract().ok();
    }
    let s = v.cast::<PyString>().ok()?;
    match s.to_cow().ok()?.as_ref() {
        "inf" => Some(f64::INFINITY),
        "-inf" => Some(f64::NEG_INFINITY),
        "nan" => Some(f64::NAN),
        _ => None,
    }
}

/// Replaces the list `dict[key]` by its columns.
pub fn columns_at(dict: &Bound<'_, PyDict>, key: &str, shape: Option<[usize; 2]>) -> PyResult<()> {
    if let Some(rows) = dict.get_item(key)?
        && let Ok(rows) = rows.cast::<PyList>()
    {
        dict.set_item(key, columns(rows, shape)?)?;
    }
    Ok(())
}

/// Each dict of the list `dict[key]`.
pub fn each<'py>(dict: &Bound<'py, PyDict>, key: &str) -> PyResult<Vec<Bound<'py, PyDict>>> {
    match dict.get_item(key)? {
        Some(list) => list
            .cast::<PyList>()?
            .iter()
            .map(|d| Ok(d.cast_into::<PyDict>()?))
            .collect(),
        None => Ok(Vec::new()),
    }
}

/// The JSON's arrays as lists: serde writes a fixed-size array (`[f64; 2]`)
/// as a tuple, which Python would keep as a tuple; JSON has only lists.
pub fn tuples_to_lists(value: &Bound<'_, PyAny>) -> PyResult<()> {
    if let Ok(dict) = value.cast::<PyDict>() {
        for (key, item) in dict.iter() {
            if let Some(list) = listed(&item)? {
                dict.set_item(key, list)?;
            }
        }
    } else if let Ok(list) = value.cast::<PyList>() {
        for (i, item) in list.iter().enumerate() {
            if let Some(inner) = listed(&item)? {
                list.set_item(i, inner)?;
            }
        }
    }
    Ok(())
}

/// `item` with its tuples as lists: the list that replaces it if it is a
/// tuple, `None` if it stays (its insides changed in place).
fn listed<'py>(item: &Bound<'py, PyAny>) -> PyResult<Option<Bound<'py, PyList>>> {
    match item.cast::<PyTuple>() {
        Ok(t) => {
            let list = PyList::new(item.py(), t.iter())?;
            tuples_to_lists(&list)?;
            Ok(Some(list))
        }
        Err(_) => {
            tuples_to_lists(item)?;
            Ok(None)
        }
    }
}
