//! Pixelbuffer's coverage (§4.7.2) as the image loop asks for it: from a column on, does the
//! fill cover the pixels (traced) or not (the background, with no ray), and up to which column.
//!
//! Two ways to know it, chosen by the order:
//! - [`ReadBack`] (orders `Whole` and `Rows`): the fill is marked in the sink before the image
//!   (`fill_volumes_rows`) and read back in chunks of [`READ_CHUNK`] pixels, as the thesis read
//!   its PGA's memory; the sink must be a [`PixelSource`].
//! - [`RowCoverage`] (`Streamed`, `Progressive`, `Pass`, and the corner rows of an antialiased
//!   image): the same fill recorded one row at a time as spans, sorted and merged, with a cursor
//!   that only moves forward, since the loop asks for increasing columns. The sink is never read.
//!
//! Either gives the loop the same runs, so every order traces the same pixels.

use core::ops::Range;

use super::fill::fill_volumes_rows;
use crate::config::Config;
use crate::optimize::sortlist::{heapsort, INSERTION_SORT_BELOW};
use crate::pixel::{PixelSink, PixelSource};
use crate::scene::Prepared;
use crate::storage::Table;

/// Pixels read back per `read_row` call (a stack buffer; no row-sized buffer is needed).
pub(crate) const READ_CHUNK: usize = 32;

/// Which pixels of a row the fill covers, asked column by column in increasing order.
pub(crate) trait Coverage<C: Config, P, S> {
    /// Ready for `row`.
    fn begin_row(&mut self, scene: &Prepared<C>, row: u16);

    /// Whether the fill covers `column` of `row`, and the column (at most `width`, past
    /// `column`) up to which that answer holds.
    fn run(&mut self, sink: &mut S, row: u16, column: u16, width: u16) -> (bool, u16);
}

/// The fill marked in the sink and read back (`on`: Pixelbuffer is on; off, every pixel is
/// traced).
pub(crate) struct ReadBack<P> {
    on: bool,
    chunk: [P; READ_CHUNK],
    length: usize,
    fill: P,
    flood: P,
}

impl<P: Copy> ReadBack<P> {
    /// With Pixelbuffer on, marks the fill of `rows` in `sink` (the flood where no object's
    /// fill reaches).
    pub(crate) fn marked<C: Config, S: PixelSink<P>>(scene: &Prepared<C>, sink: &mut S, rows: Range<u16>, (fill, flood): (P, P)) -> Self {
        let on = scene.optimizations.pixelbuffer;
        if on {
            fill_volumes_rows(scene, sink, fill, flood, rows);
        }
        Self { on, chunk: [fill; READ_CHUNK], length: 0, fill, flood }
    }
}

impl<C: Config, P: Copy + PartialEq, S: PixelSink<P> + PixelSource<P>> Coverage<C, P, S> for ReadBack<P> {
    #[inline(always)]
    fn begin_row(&mut self, _scene: &Prepared<C>, _row: u16) {}

    #[inline(always)]
    fn run(&mut self, sink: &mut S, row: u16, column: u16, width: u16) -> (bool, u16) {
        if !self.on {
            return (true, width);
        }
        // Read the row back a chunk at a time, each chunk before any of it is written.
        let offset = usize::from(column) % READ_CHUNK;
        if offset == 0 {
            self.chunk = [self.fill; READ_CHUNK];
            self.length = usize::from(width - column).min(READ_CHUNK);
            if let Some(part) = self.chunk.get_mut(..self.length) {
                sink.read_row(column, row, part);
            }
        }
        // Only a pixel that still holds the flood colour was never filled: the run of them in
        // this chunk is the background at once.
        let flood = self.flood;
        let run = self.chunk.get(offset..self.length).map_or(0, |rest| rest.iter().take_while(|value| **value == flood).count());
        if run > 0 {
            (false, column + run as u16)
        } else {
            (true, column + 1)
        }
    }
}

/// The fill of one row, as spans of columns (`start`, `end` exclusive): which of its pixels the
/// render with Pixelbuffer traces. Each object marks at most one span a row; should more come
/// than there is room for, the whole row counts as covered (a traced pixel outside the fill is
/// the background anyway).
pub(crate) struct RowCoverage<C: Config> {
    spans: C::PerObject<(u16, u16)>,
    count: usize,
    overflowed: bool,
    /// The first span that may still reach the columns asked.
    cursor: usize,
}

impl<C: Config> RowCoverage<C> {
    /// No span yet: covers nothing (room for a span of each of `objects`).
    #[inline(always)]
    pub(crate) fn empty(objects: usize) -> Self {
        Self { spans: C::PerObject::filled(objects, (0, 0)), count: 0, overflowed: false, cursor: 0 }
    }

    /// With Pixelbuffer on, an empty coverage for the scene's objects, to be
    /// [`RowCoverage::refill`]ed row after row (made once a render: on a host its room is
    /// allocated).
    pub(crate) fn for_scene(scene: &Prepared<C>) -> Option<Self> {
        scene.optimizations.pixelbuffer.then(|| Self::empty(scene.objects.len()))
    }

    /// The coverage of `row`, in place of the earlier row's: its spans sorted and merged.
    pub(crate) fn refill(&mut self, scene: &Prepared<C>, row: u16) {
        self.count = 0;
        self.overflowed = false;
        fill_volumes_rows(scene, self, true, false, row..row.saturating_add(1));
        self.merge();
    }

    /// Sorts the spans by their start (an insertion sort when a row has a few, else a
    /// heapsort) and merges those that overlap or touch, so that they are disjoint, in order
    /// and never adjacent; the cursor back at the first.
    pub(super) fn merge(&mut self) {
        self.cursor = 0;
        if self.overflowed {
            return;
        }
        let Some(spans) = self.spans.slots_mut().get_mut(..self.count) else { return };
        if C::MAX_OBJECTS >= INSERTION_SORT_BELOW && spans.len() >= INSERTION_SORT_BELOW {
            // Equal starts may come in any order: they merge alike.
            let len = spans.len();
            heapsort(spans, len, |spans: &[(u16, u16)], i, j| matches!((spans.get(i), spans.get(j)), (Some(a), Some(b)) if a.0 < b.0), |spans: &mut [(u16, u16)], i, j| {
                if i < spans.len() && j < spans.len() {
                    spans.swap(i, j);
                }
            });
        } else {
            for next in 1..spans.len() {
                let Some(&moving) = spans.get(next) else { break };
                let mut slot = next;
                while let Some(&before) = slot.checked_sub(1).and_then(|previous| spans.get(previous)) {
                    if before.0 <= moving.0 {
                        break;
                    }
                    if let Some(place) = spans.get_mut(slot) {
                        *place = before;
                    }
                    slot -= 1;
                }
                if let Some(place) = spans.get_mut(slot) {
                    *place = moving;
                }
            }
        }
        let mut merged: usize = 0;
        for next in 0..spans.len() {
            let Some(&(start, end)) = spans.get(next) else { break };
            match merged.checked_sub(1).and_then(|last| spans.get_mut(last)) {
                Some(last) if start <= last.1 => last.1 = last.1.max(end),
                _ => {
                    if let Some(place) = spans.get_mut(merged) {
                        *place = (start, end);
                    }
                    merged += 1;
                }
            }
        }
        self.count = merged;
    }

    /// Whether the fill covers `column` (asked in increasing order after a refill), and the
    /// column (at most `width`) up to which that answer holds.
    #[inline(always)]
    pub(crate) fn run(&mut self, column: u16, width: u16) -> (bool, u16) {
        if self.overflowed {
            return (true, width);
        }
        let spans = self.spans.slots().get(..self.count).unwrap_or(&[]);
        while spans.get(self.cursor).is_some_and(|&(_, end)| end <= column) {
            self.cursor += 1;
        }
        match spans.get(self.cursor) {
            Some(&(start, end)) if start <= column => (true, end.min(width)),
            Some(&(start, _)) => (false, start.min(width)),
            None => (false, width),
        }
    }

    /// Whether the fill covers `column` (asked in increasing order after a refill).
    #[cfg(any(feature = "antialias", test))]
    #[inline(always)]
    pub(crate) fn covers(&mut self, column: u16) -> bool {
        self.run(column, u16::MAX).0
    }

    /// The merged spans (`start`, `end`), or `None` when there were more than the coverage
    /// holds and the whole row counts as covered.
    #[cfg(test)]
    pub(crate) fn spans(&self) -> Option<&[(u16, u16)]> {
        (!self.overflowed).then(|| self.spans.slots().get(..self.count).unwrap_or(&[]))
    }
}

/// Pixelbuffer off: `None`, every pixel traced.
impl<C: Config, P, S> Coverage<C, P, S> for Option<RowCoverage<C>> {
    #[inline(always)]
    fn begin_row(&mut self, scene: &Prepared<C>, row: u16) {
        if let Some(coverage) = self.as_mut() {
            coverage.refill(scene, row);
        }
    }

    #[inline(always)]
    fn run(&mut self, _sink: &mut S, _row: u16, column: u16, width: u16) -> (bool, u16) {
        match self.as_mut() {
            Some(coverage) => coverage.run(column, width),
            None => (true, width),
        }
    }
}

impl<C: Config> PixelSink<bool> for RowCoverage<C> {
    fn set_pixel(&mut self, x: u16, y: u16, filled: bool) {
        self.mark_row(x, y, 1, filled);
    }

    fn fill_row(&mut self, x: u16, y: u16, width: u16, filled: bool) {
        self.mark_row(x, y, width, filled);
    }

    /// The flood (`false`) comes first and covers nothing; each fill (`true`) is a span.
    fn mark_row(&mut self, x: u16, _y: u16, width: u16, filled: bool) {
        if !filled || width == 0 {
            return;
        }
        match self.spans.slots_mut().get_mut(self.count) {
            Some(span) => {
                *span = (x, x.saturating_add(width));
                self.count += 1;
            }
            None => self.overflowed = true,
        }
    }
}
