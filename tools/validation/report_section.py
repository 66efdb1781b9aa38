"""Writing one generated section of validation/REPORT.md between its begin and end markers: replaced where the report
has it, else appended; written atomically (a temporary file renamed over the report).  Used by the tools that write
their own sections (hydro_section, rotating_section, tools/hindered_settling.py); tools/validation_report.py keeps
those sections when it rewrites the report."""
import os


def write_section(report, begin, end, new):
    """Puts the text `new` (which starts with `begin` and ends with `end`) into the report file."""
    text = open(report).read() if os.path.exists(report) else ""
    if begin in text and end in text:
        a, b = text.index(begin), text.index(end) + len(end)
        text = text[:a] + new + text[b:]
    else:
        text = text.rstrip("\n") + "\n\n" + new + "\n"
    tmp = report + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, report)
