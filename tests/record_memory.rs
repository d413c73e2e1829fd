//! Records read in one long process (a notebook kernel, an explorer
//! session) are shared while runs hold them and freed when the last holder
//! drops them: the registry keeps only weak references, prunes the dead
//! ones as it grows, and the sample memory returns to the allocator.
//!
//! The registry is global to the process and these tests count its live
//! records, so they run one at a time ([`SERIAL`]); this binary has no
//! other test. A counting global allocator, private to this binary, gives
//! the bytes in use.

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicIsize, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, Weak};

use pounding::model::record::{self, Record, intern, live_records, registry_len};
use pounding::model::{Excitation, Params, SET1};

/// Bytes allocated and not yet freed, by every thread of this binary.
static IN_USE: AtomicIsize = AtomicIsize::new(0);

struct Counting;

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        IN_USE.fetch_add(layout.size() as isize, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        IN_USE.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn in_use() -> isize {
    IN_USE.load(Ordering::Relaxed)
}

/// One test at a time: each counts the records live in the whole process.
static SERIAL: Mutex<()> = Mutex::new(());

fn serial() -> MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

/// Samples per record file: small, but enough that the samples (three
/// series of 8-byte numbers) dwarf the registry's bookkeeping.
const SAMPLES: usize = 400;

/// Writes `count` distinct plain records (`time acceleration` in g) named
/// `{prefix}-NNNN.csv` into `dir`, and returns their paths.
fn write_records(dir: &Path, prefix: &str, count: usize) -> Vec<String> {
    (0..count)
        .map(|i| {
            let path = dir.join(format!("{prefix}-{i:04}.csv"));
            let text: String = (0..SAMPLES)
                .map(|k| {
                    let t = k as f64 * 0.01;
                    let a = 0.1 * (1.0 + i as f64 * 1e-3) * (7.0 * t).sin();
                    format!("{t} {a}\n")
                })
                .collect();
            std::fs::write(&path, text).unwrap();
            path.to_str().unwrap().to_string()
        })
        .collect()
}

/// A run's parameter set under the record at `path`, as `--excitation
/// record:PATH` makes it.
fn set_under(path: &str) -> Params {
    Params {
        excitation: Excitation::parse(&format!("record:{path}")).unwrap(),
        ..SET1
    }
}

fn record_of(p: &Params) -> &Arc<Record> {
    match &p.excitation {
        Excitation::Record(m) => &m.record,
        other => panic!("not a record: {other}"),
    }
}

/// 2,000 distinct record files read in one process, each held by a
/// parameter set: all 2,000 are live while held; once every set is
/// dropped none is, their samples' memory is back with the allocator, and
/// the registry prunes the dead entries as later reads come, so its length
/// stays within twice the records held rather than growing with every
/// file ever read.
#[test]
fn records_no_run_holds_are_freed_and_the_registry_is_pruned() {
    let _serial = serial();
    let dir = tempfile::tempdir().unwrap();
    const COUNT: usize = 2_000;
    // Warm up what lives for the process whatever is read (rayon's pool,
    // the registries' tables), so that the baseline holds it.
    drop(set_under(&write_records(dir.path(), "warm", 1)[0]));
    let paths = write_records(dir.path(), "first", COUNT);
    assert_eq!(live_records(), 0);
    let baseline = in_use();

    let sets: Vec<Params> = paths.iter().map(|p| set_under(p)).collect();
    let weak: Vec<Weak<Record>> = sets.iter().map(|p| Arc::downgrade(record_of(p))).collect();
    assert_eq!(live_records(), COUNT);
    let samples_bytes = (COUNT * 3 * SAMPLES * std::mem::size_of::<f64>()) as isize;
    let held = in_use() - baseline;
    assert!(
        held >= samples_bytes,
        "{held} bytes held, below the samples' {samples_bytes}"
    );

    drop(sets);
    assert_eq!(live_records(), 0);
    assert!(weak.iter().all(|w| w.upgrade().is_none()));
    // What stays until the next pruning is each dead entry's husk (the
    // key and the weak reference's block), not its samples.
    let left = in_use() - baseline;
    assert!(
        left < samples_bytes / 10,
        "{left} bytes still in use after every holder was dropped (samples: {samples_bytes})"
    );
    drop(weak);

    // Two more batches of new files, each held then dropped: without
    // pruning the registry would hold 6,000 entries.
    for batch in ["second", "third"] {
        let paths = write_records(dir.path(), batch, COUNT);
        let sets: Vec<Params> = paths.iter().map(|p| set_under(p)).collect();
        assert_eq!(live_records(), COUNT);
        assert!(
            registry_len() <= 2 * COUNT,
            "{batch}: {} entries for {COUNT} live records",
            registry_len()
        );
        drop(sets);
        assert_eq!(live_records(), 0);
    }
}

/// A record held by a live run's parameter set is not freed, however many
/// other holders drop it: it is shared (read once, not again) while any
/// set holds it, and freed with the last.
#[test]
fn a_record_held_by_a_run_is_not_freed() {
    let _serial = serial();
    let dir = tempfile::tempdir().unwrap();
    let path = &write_records(dir.path(), "held", 1)[0];
    let p = set_under(path);
    let weak = Arc::downgrade(record_of(&p));
    // The loader's own handle and a second set share the one record.
    let again = record::load(path).unwrap();
    assert!(Arc::ptr_eq(&again, record_of(&p)));
    let q = p.clone();
    drop(again);
    drop(p);
    assert!(weak.upgrade().is_some(), "freed while a set holds it");
    assert_eq!(live_records(), 1);
    // A run of the remaining set, on another thread, while this one drops
    // every other handle: the record stays for the run.
    let run = std::thread::spawn(move || {
        let result = pounding::solver::solve(&q, &mut ());
        (result.completed, Arc::strong_count(record_of(&q)))
    });
    let (completed, holders) = run.join().unwrap();
    assert!(completed);
    assert_eq!(holders, 1);
    // The thread's set is gone with it: so is the record.
    assert!(weak.upgrade().is_none());
    assert_eq!(live_records(), 0);
}

/// Records built in memory (a synthetic suite) are shared while held: an
/// equal record interned again is the same one. Once every holder has
/// dropped it, it is freed, and an equal record built later is new.
#[test]
fn an_interned_record_is_shared_while_held_and_freed_after() {
    let _serial = serial();
    let samples = || -> Vec<f64> { (0..50).map(|k| (0.3 * k as f64).sin()).collect() };
    let first = intern(Record::from_samples("built", 0.02, samples()));
    let second = intern(Record::from_samples("built", 0.02, samples()));
    assert!(Arc::ptr_eq(&first, &second));
    // A record of the same name but other samples is its own.
    let other = intern(Record::from_samples("built", 0.04, samples()));
    assert!(!Arc::ptr_eq(&first, &other));
    assert_eq!(live_records(), 2);
    let weak = Arc::downgrade(&first);
    drop((first, second, other));
    assert!(weak.upgrade().is_none());
    assert_eq!(live_records(), 0);
    let later = intern(Record::from_samples("built", 0.02, samples()));
    assert!(weak.upgrade().is_none());
    assert_eq!(live_records(), 1);
    drop(later);
    assert_eq!(live_records(), 0);
}
