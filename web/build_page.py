"""Writes the viewer as one HTML file (docs/web.md): web/index.html with the WebAssembly module
(the classic-script build, the wasm inside it), the bundled example scenes and web/app.js
inlined (web/draw.js, web/panels.js, web/assembly.js and web/app.js, in that order, one script), so that the page works opened from disk (file://) and from any static host.

    build_page.py MODULE_JS EXAMPLES_DIR OUTPUT_HTML
"""

import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def inline(js: str) -> str:
    # A script's text ends at the first "</script"; nothing else needs escaping.
    return js.replace("</script", "<\\/script")


def main():
    module_js, examples_dir, output = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    examples = {}
    for path in sorted(examples_dir.glob("*.json")):
        doc = json.loads(path.read_text())
        if isinstance(doc, dict) and ("body" in doc or "bodies" in doc):  # scenes and assemblies; force sets are drawn by `label`
            examples[path.stem] = doc
    page = (HERE / "index.html").read_text()
    for mark, text in (("/*MOMENTLAB_MODULE*/", module_js.read_text()),
                       ("/*MOMENTLAB_EXAMPLES*/", json.dumps(examples)),
                       ("/*MOMENTLAB_APP*/", "\n".join((HERE / name).read_text() for name in ("draw.js", "panels.js", "assembly.js", "app.js")))):
        assert page.count(mark) == 1, mark
        page = page.replace(mark, inline(text))
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(page)


if __name__ == "__main__":
    main()
