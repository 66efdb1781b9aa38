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


def sections_in(text, names, begin, end):
    """The generated sections of a report's text, one per name that has both markers (begin.format(name) ..
    end.format(name)), each from its begin to its end marker."""
    out = []
    for name in names:
        b, e = begin.format(name), end.format(name)
        if b in text and e in text:
            out.append(text[text.index(b):text.index(e) + len(e)])
    return out


def study_section_main(section, begin, end, argv):
    """The command line of a tool that writes one study's section: STUDY REPORT [COMMIT].  Calls
    section(study, commit, png) (png: the report's folder / the study's name .png), prints the section and writes
    it between begin.format(name) and end.format(name); returns (study, commit)."""
    import subprocess
    study, report = argv[1], argv[2]
    commit = argv[3] if len(argv) > 3 else subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    name = os.path.basename(os.path.normpath(study))
    png = os.path.join(os.path.dirname(report) or ".", name + ".png")
    new = "\n".join(section(study, commit, png))
    print(new)
    write_section(report, begin.format(name), end.format(name), new)
    return study, commit
