//! Tables printed both as aligned text (the terminal) and as Markdown (BENCHMARKS.md).

pub struct Table {
    pub title: String,
    pub header: Vec<String>,
    /// Columns from this one on are right-aligned (numbers).
    pub numeric_from: usize,
    pub rows: Vec<Vec<String>>,
    /// Printed under the table.
    pub notes: Vec<String>,
}

impl Table {
    pub fn new(title: &str, header: &[&str], numeric_from: usize) -> Table {
        Table {
            title: title.to_owned(),
            header: header.iter().map(|s| s.to_string()).collect(),
            numeric_from,
            rows: Vec::new(),
            notes: Vec::new(),
        }
    }

    pub fn text(&self) -> String {
        let mut widths: Vec<usize> = self.header.iter().map(|h| h.chars().count()).collect();
        for r in &self.rows {
            for (w, c) in widths.iter_mut().zip(r) {
                *w = (*w).max(c.chars().count());
            }
        }
        let line = |cells: &[String]| {
            let mut s = String::new();
            for (i, (c, w)) in cells.iter().zip(&widths).enumerate() {
                if i >= self.numeric_from {
                    s += &format!("{c:>w$}  ");
                } else {
                    s += &format!("{c:<w$}  ");
                }
            }
            s.trim_end().to_owned() + "\n"
        };
        let mut out = format!("\n{}\n\n", self.title);
        out += &line(&self.header);
        out += &"-".repeat(widths.iter().sum::<usize>() + 2 * widths.len().saturating_sub(1));
        out += "\n";
        for r in &self.rows {
            out += &line(r);
        }
        for n in &self.notes {
            out += &format!("{n}\n");
        }
        out
    }

    pub fn markdown(&self) -> String {
        let mut out = format!("\n### {}\n\n", self.title);
        out += &format!("| {} |\n", self.header.join(" | "));
        let align: Vec<&str> = (0..self.header.len())
            .map(|i| {
                if i >= self.numeric_from {
                    "---:"
                } else {
                    "---"
                }
            })
            .collect();
        out += &format!("|{}|\n", align.join("|"));
        for r in &self.rows {
            let cells: Vec<String> = r.iter().map(|c| c.replace('|', "\\|")).collect();
            out += &format!("| {} |\n", cells.join(" | "));
        }
        if !self.notes.is_empty() {
            out += "\n";
            for n in &self.notes {
                out += &format!("{n}\n");
            }
        }
        out
    }
}

/// Today's date (UTC) as YYYY-MM-DD, from the system clock.
pub fn today() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    // Days since 1970-01-01 to a proleptic Gregorian date (Howard Hinnant's method).
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// The CPU model from /proc/cpuinfo.
pub fn cpu_model() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".into())
}

pub fn kernel() -> String {
    std::fs::read_to_string("/proc/sys/kernel/osrelease")
        .map(|s| s.trim().to_owned())
        .unwrap_or_else(|_| "unknown".into())
}

/// The 1-, 5- and 15-minute load averages, to judge how quiet the machine was.
pub fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|| "unknown".into())
}
