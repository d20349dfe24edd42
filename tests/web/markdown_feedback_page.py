#!/usr/bin/env python3
"""The pages of scripts/markdown_feedback_check.sh: the grader's Markdown feedback rendered by cmark, for Chromium.

markdown_feedback_page.py html RESULTS MODE HTML   writes the page of RESULTS's feedback (each failed test's
    Markdown, and the submission's) rendered by cmark in MODE (safe, or unsafe: raw HTML kept), with
    markdown_feedback_check.js, the page's own check, and what each test's Markdown holds (the check compares);
    exit status 1 when a picture embedded in the Markdown is not byte for byte pictures/test-N.png, or no whole PNG.
markdown_feedback_page.py verdict DOM   prints the findings the page's check wrote into the dumped DOM; exit
    status 0 when there is no problem.
markdown_feedback_page.py spoil RESULTS COPY HOW   COPY is RESULTS with the first picture's data URL cut short
    (HOW = broken) or its image left out of the Markdown (HOW = missing), with RESULTS's pictures/ beside it.
"""
import base64, html, json, os, re, shutil, struct, subprocess, sys, zlib

IMAGE = re.compile(r"!\[[^\]]*\]\(data:image/png;base64,([A-Za-z0-9+/=]*)\)")


def png_size(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        return None
    return list(struct.unpack(">II", data[16:24]))


def png_problem(data):
    """What makes `data` no whole PNG (a chunk's CRC, image data that does not inflate to every row), or ""."""
    if png_size(data) is None:
        return "no PNG header"
    width, height, depth, colour = struct.unpack(">IIBB", data[16:26])
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour)
    if channels is None:
        return "an unknown PNG colour type %d" % colour
    i, pixels, ended = 8, b"", False
    while i + 12 <= len(data) and not ended:
        length, kind = struct.unpack(">I4s", data[i:i + 8])
        body = data[i + 8:i + 8 + length]
        if len(body) < length or data[i + 8 + length:i + 12 + length] != struct.pack(
                ">I", zlib.crc32(kind + body)):
            return "its %s chunk is cut short or fails its CRC" % kind.decode(errors="replace")
        pixels += body if kind == b"IDAT" else b""
        ended = kind == b"IEND"
        i += 12 + length
    if not ended:
        return "no IEND chunk"
    try:
        rows = zlib.decompress(pixels)
    except zlib.error as e:
        return "its image data does not inflate (%s)" % e
    if len(rows) != height * (1 + (width * channels * depth + 7) // 8):
        return "its image data holds %d bytes, not %dx%d pixels" % (len(rows), width, height)
    return ""


def failed_tests(results):
    return [t for t in results.get("tests", [])
            if t.get("status") == "failed" or t.get("score", 0) < t.get("max_score", 0)]


def expected(markdown, picture):
    """What the rendered Markdown must hold: counted from its source, outside fenced blocks."""
    fences, headings, spans, inside = 0, 0, 0, None
    for line in markdown.split("\n"):
        fence = re.match(r" {0,3}(`{3,}|~{3,})", line)
        if inside:
            if fence and fence.group(1)[0] == inside[0] and len(fence.group(1)) >= len(inside) \
                    and not line.strip().strip(inside[0]):
                inside = None
            continue
        if fence:
            fences, inside = fences + 1, fence.group(1)
            continue
        if re.match(r" {0,3}#{1,6}(\s|$)", line):
            headings += 1
        spans += len(re.findall(r"(?<![\\`])`[^`\n]+`(?!`)", line))
    return {"headings": headings, "code_spans": spans, "fences": fences,
            "details": len(re.findall(r"<details[\s>]", markdown)),
            "pictures": [picture] if picture else []}


def page(results_path, mode, html_path):
    results = json.load(open(results_path))
    pictures = os.path.join(os.path.dirname(results_path), "pictures")
    sections, problems = [], []
    entries = [("submission", "", results.get("output", ""))]
    entries += [(t.get("number", str(i)), t.get("name", ""), t.get("output", ""))
                for i, t in enumerate(failed_tests(results))]
    for number, name, markdown in entries:
        picture_file = os.path.join(pictures, "test-%s.png" % number)
        picture = None
        if number != "submission" and os.path.isfile(picture_file):
            data = open(picture_file, "rb").read()
            picture = {"file": picture_file, "size": png_size(data)}
            if png_problem(data):
                problems.append("test %s: %s is no whole PNG: %s" % (number, picture_file, png_problem(data)))
            for embedded in IMAGE.finditer(markdown):
                try:
                    same = base64.b64decode(embedded.group(1) + "=" * (-len(embedded.group(1)) % 4)) == data
                except ValueError:
                    same = False
                if not same:
                    problems.append("test %s: the picture in the feedback is not %s" % (number, picture_file))
        flags = [] if mode == "safe" else ["--unsafe"]
        rendered = subprocess.run(["cmark"] + flags, input=markdown.encode(), stdout=subprocess.PIPE,
                                  check=True).stdout.decode()
        sections.append('<section class="test" data-number="%s" data-expected="%s">\n<h2 class="title">%s %s</h2>\n'
                        '<div class="feedback">\n%s</div>\n</section>\n'
                        % (html.escape(number), html.escape(json.dumps(expected(markdown, picture))),
                           html.escape(name and number), html.escape(name or "The submission"), rendered))
    script = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "markdown_feedback_check.js")).read()
    with open(html_path, "w") as f:
        f.write('<!DOCTYPE html>\n<html><head><meta charset="utf-8"><title>feedback (cmark %s)</title>\n'
                '<script>window.failedImages = new Set(); addEventListener("error", (e) => {'
                ' if (e.target instanceof HTMLImageElement) failedImages.add(e.target); }, true);</script>\n'
                '<style>body{font-family:sans-serif;margin:16px;max-width:1200px}img{max-width:100%%}'
                '.test{border:1px solid #ccc;padding:0 12px;margin-bottom:16px}'
                'code{background:#f3f3f3}</style></head>\n<body data-mode="%s">\n%s<pre id="verdict"></pre>\n'
                '<script>\n%s</script>\n'
                '</body></html>\n' % (mode, mode, "".join(sections), script))
    print("  %d failed tests, %d with a picture" % (len(entries) - 1, sum(1 for _, _, m in entries if IMAGE.search(m))))
    for problem in problems:
        print("  " + problem)
    return not problems


def verdict(dom_path):
    dom = open(dom_path, errors="replace").read()
    found = re.search(r'<pre id="verdict">(.*?)</pre>', dom, re.S)
    text = html.unescape(found.group(1)) if found else ""
    if not text.strip():
        print("  the page's script wrote no verdict (it did not run, or did not finish)")
        return 1
    findings = json.loads(text)
    print("  in Chromium: %d sections, %d images loaded, %d code spans, %d details, %d headings" % (
        findings["sections"], findings["images"], findings["code"], findings["details"], findings["headings"]))
    for problem in findings["problems"]:
        print("  " + problem)
    return 1 if findings["problems"] else 0


def spoil(results_path, copy_path, how):
    results = json.load(open(results_path))
    for test in failed_tests(results):
        image = IMAGE.search(test.get("output", ""))
        if not image:
            continue
        if how == "broken":
            start = image.group(0).index("base64,") + len("base64,")
            spoiled = image.group(0)[:start + 40] + ")"
        else:
            spoiled = ""
        test["output"] = test["output"].replace(image.group(0), spoiled)
        break
    else:
        sys.exit("no picture to spoil in " + results_path)
    os.makedirs(os.path.dirname(copy_path), exist_ok=True)
    json.dump(results, open(copy_path, "w"))
    pictures = os.path.join(os.path.dirname(results_path), "pictures")
    shutil.copytree(pictures, os.path.join(os.path.dirname(copy_path), "pictures"), dirs_exist_ok=True)


if sys.argv[1] == "html":
    sys.exit(0 if page(sys.argv[2], sys.argv[3], sys.argv[4]) else 1)
elif sys.argv[1] == "verdict":
    sys.exit(verdict(sys.argv[2]))
elif sys.argv[1] == "spoil":
    spoil(sys.argv[2], sys.argv[3], sys.argv[4])
