//! Fast tabular output of points: one point per line in text, CSV, 32-bit
//! integer or JSON form, written through one buffered writer.
//!
//! Rows are formatted into a byte buffer (integers with `itoa`, floats with
//! `ryu`) that is handed to the writer in large chunks, so tens of millions
//! of values print in seconds. Write errors (including a closed pipe) are
//! returned, never panicked on; `main` treats a broken pipe as success.

use std::io::{self, Write};

use clap::ValueEnum;

/// How points are printed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Decimal values in [0,1), space-separated: the shortest decimal that
    /// parses back to exactly word * 2^-32.
    Text,
    /// Comma-separated decimal values with a header line `x0,x1,...`.
    Csv,
    /// The 32-bit digit words floor(x * 2^32) as integers, space-separated.
    U32,
    /// One JSON array of arrays of decimal values.
    Json,
}

/// Flush the buffer to the writer once it holds this many bytes.
const CHUNK: usize = 1 << 16;

/// Writes rows of values in one [`Format`].
pub struct TableWriter<W: Write> {
    out: W,
    format: Format,
    buf: Vec<u8>,
    rows: u64,
    ints: itoa::Buffer,
    floats: ryu::Buffer,
}

impl<W: Write> TableWriter<W> {
    /// Starts a table: writes the CSV header (`columns` names) or the JSON
    /// opening bracket.
    pub fn new(out: W, format: Format, columns: &[String]) -> Self {
        let mut w = TableWriter {
            out,
            format,
            buf: Vec::with_capacity(CHUNK + 4096),
            rows: 0,
            ints: itoa::Buffer::new(),
            floats: ryu::Buffer::new(),
        };
        match format {
            Format::Csv => {
                w.buf.extend_from_slice(columns.join(",").as_bytes());
                w.buf.push(b'\n');
            }
            Format::Json => w.buf.push(b'['),
            Format::Text | Format::U32 => {}
        }
        w
    }

    fn separator(&self) -> u8 {
        match self.format {
            Format::Csv | Format::Json => b',',
            Format::Text | Format::U32 => b' ',
        }
    }

    fn begin_row(&mut self) {
        if self.format == Format::Json {
            if self.rows > 0 {
                self.buf.push(b',');
            }
            self.buf.extend_from_slice(b"\n[");
        }
    }

    fn end_row(&mut self) -> io::Result<()> {
        if self.format == Format::Json {
            self.buf.push(b']');
        } else {
            self.buf.push(b'\n');
        }
        self.rows += 1;
        if self.buf.len() >= CHUNK {
            self.out.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(())
    }

    fn push_float(&mut self, v: f64) {
        // ryu prints `0.0` for zero, which parses everywhere; keep it.
        self.buf.extend_from_slice(self.floats.format(v).as_bytes());
    }

    /// Writes one point given as 32-bit digit words: integers for
    /// [`Format::U32`], the exact value `word * 2^-32` otherwise.
    pub fn write_words(&mut self, words: &[u32]) -> io::Result<()> {
        self.begin_row();
        let sep = self.separator();
        for (j, &w) in words.iter().enumerate() {
            if j > 0 {
                self.buf.push(sep);
            }
            if self.format == Format::U32 {
                self.buf.extend_from_slice(self.ints.format(w).as_bytes());
            } else {
                self.push_float(lowdisc::to_f64(w));
            }
        }
        self.end_row()
    }

    /// Writes one row of real values (not available in [`Format::U32`]; the
    /// caller rejects that combination).
    pub fn write_floats(&mut self, values: &[f64]) -> io::Result<()> {
        self.begin_row();
        let sep = self.separator();
        for (j, &v) in values.iter().enumerate() {
            if j > 0 {
                self.buf.push(sep);
            }
            self.push_float(v);
        }
        self.end_row()
    }

    /// Closes the JSON array and flushes everything.
    pub fn finish(mut self) -> io::Result<()> {
        if self.format == Format::Json {
            self.buf.extend_from_slice(b"\n]\n");
        }
        self.out.write_all(&self.buf)?;
        self.buf.clear();
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(format: Format, rows: &[&[u32]]) -> String {
        let mut out = Vec::new();
        let mut w = TableWriter::new(&mut out, format, &["x0".into(), "x1".into()]);
        for r in rows {
            w.write_words(r).unwrap();
        }
        w.finish().unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn each_format_lays_out_rows() {
        let rows: &[&[u32]] = &[&[0, 1 << 31], &[3 << 30, u32::MAX]];
        assert_eq!(
            table(Format::U32, rows),
            "0 2147483648\n3221225472 4294967295\n"
        );
        assert_eq!(
            table(Format::Text, rows),
            "0.0 0.5\n0.75 0.9999999997671694\n"
        );
        assert_eq!(
            table(Format::Csv, rows),
            "x0,x1\n0.0,0.5\n0.75,0.9999999997671694\n"
        );
        assert_eq!(
            table(Format::Json, rows),
            "[\n[0.0,0.5],\n[0.75,0.9999999997671694]\n]\n"
        );
    }

    #[test]
    fn decimal_output_round_trips_every_word() {
        let words: Vec<u32> = (0..2000u32)
            .map(|k| k.wrapping_mul(2_654_435_761))
            .chain([1, u32::MAX])
            .collect();
        let text = table(Format::Text, &[&words]);
        for (tok, &w) in text.split_whitespace().zip(&words) {
            let x: f64 = tok.parse().unwrap();
            assert_eq!((x * 4_294_967_296.0).floor() as u32, w, "{tok}");
        }
    }

    #[test]
    fn many_rows_are_all_written() {
        let row = [u32::MAX; 8];
        let mut out = Vec::new();
        let mut w = TableWriter::new(&mut out, Format::U32, &[]);
        for _ in 0..10_000 {
            w.write_words(&row).unwrap();
        }
        w.finish().unwrap();
        assert_eq!(out.len(), 10_000 * (8 * 11));
    }
}
