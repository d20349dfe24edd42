// The check inside a page of tests/web/markdown_feedback_page.py, run on the load event (every image has loaded or
// failed to by then; the page's head records the <img> that fired an error event): what a student would see of each
// test's feedback against what its Markdown holds (the section's data-expected), its findings as JSON in
// <pre id="verdict"> for scripts/markdown_feedback_check.sh to read from the dumped DOM.
addEventListener("load", () => {
  try {
    check();
  } catch (e) {
    document.getElementById("verdict").textContent = JSON.stringify(
      {problems: [`the page's check threw: ${e}`], sections: 0, images: 0, code: 0, details: 0, headings: 0});
  }
});

function check() {
  const failed = window.failedImages;  // the <img> that fired an error event, recorded by the page's head
  const problems = [];
  const counts = {sections: 0, images: 0, code: 0, details: 0, headings: 0};
  // Laid out and rendered: a closed <details> keeps its folded children laid out under content-visibility: hidden.
  const shown = (e) => e.getClientRects().length > 0 && e.checkVisibility();
  const raw = [["![", "an image's Markdown"], ["```", "a code fence"], ["**", "bold's Markdown"],
               ["](data:", "a data URL"], ["<details", "a <details> tag"], ["<summary", "a <summary> tag"],
               ["</", "a closing HTML tag"]];
  const visibleText = (feedback) => {
    let text = feedback.innerText;
    for (const pre of feedback.querySelectorAll("pre")) text = text.replace(pre.innerText, "");
    return text;
  };
  const checkText = (where, text, state) => {
    for (const [syntax, what] of raw) {
      if (text.includes(syntax)) problems.push(`${where}: ${what} (${syntax}) shows as text${state}`);
    }
    const escape = text.match(/\\[!-\/:-@\[-`{-~]/);
    if (escape) problems.push(`${where}: a backslash escape (${escape[0]}) shows as text${state}`);
  };
  for (const section of document.querySelectorAll("section.test")) {
    counts.sections++;
    const where = `test ${section.dataset.number}`;
    const want = JSON.parse(section.dataset.expected);
    const feedback = section.querySelector(".feedback");
    const images = [...feedback.querySelectorAll("img")];
    if (images.length !== want.pictures.length) {
      problems.push(`${where}: ${images.length} <img> in the feedback, ${want.pictures.length} expected` +
                    (want.pictures.length ? ` (${want.pictures[0].file} is there)` : ""));
    }
    for (const [i, img] of images.entries()) {
      const decoded = !failed.has(img);
      const src = img.getAttribute("src") || "";
      if (!src.startsWith("data:image/png;base64,")) {
        problems.push(`${where}: <img> ${i} is not a data:image/png URL (${src.slice(0, 40)})`);
      }
      if (!img.complete || img.naturalWidth === 0 || !decoded) {
        problems.push(`${where}: <img> ${i} did not load (complete ${img.complete}, naturalWidth ` +
                      `${img.naturalWidth}, decodes ${decoded})`);
        continue;
      }
      counts.images++;
      const size = want.pictures[i] && want.pictures[i].size;
      if (size && (img.naturalWidth !== size[0] || img.naturalHeight !== size[1])) {
        problems.push(`${where}: <img> ${i} is ${img.naturalWidth}x${img.naturalHeight}, the picture ` +
                      `${size[0]}x${size[1]}`);
      }
      // Chromium shows what it could decode of a picture cut short or corrupted, and leaves the rows after that
      // transparent: the pictures are opaque, so their last row must hold a painted pixel.
      const canvas = document.createElement("canvas");
      [canvas.width, canvas.height] = [img.naturalWidth, img.naturalHeight];
      const context = canvas.getContext("2d");
      context.drawImage(img, 0, 0);
      const last = context.getImageData(0, img.naturalHeight - 1, img.naturalWidth, 1).data;
      if (!last.some((value, k) => k % 4 === 3 && value > 0)) {
        problems.push(`${where}: <img> ${i} decodes only in part (its last row is transparent)`);
      }
      const box = img.getBoundingClientRect();
      if (box.width < 1 || box.height < 1 || !shown(img)) problems.push(`${where}: <img> ${i} is not shown`);
      if (!img.alt) problems.push(`${where}: <img> ${i} has no alt text`);
    }
    const headings = feedback.querySelectorAll("h1, h2, h3, h4, h5, h6").length;
    counts.headings += headings;
    if (headings !== want.headings) problems.push(`${where}: ${headings} headings, ${want.headings} expected`);
    const spans = [...feedback.querySelectorAll("code")].filter((c) => !c.closest("pre")).length;
    counts.code += spans;
    if (spans !== want.code_spans) problems.push(`${where}: ${spans} <code> spans, ${want.code_spans} expected`);
    const blocks = feedback.querySelectorAll("pre > code").length;
    if (blocks !== want.fences) problems.push(`${where}: ${blocks} <pre><code> blocks, ${want.fences} expected`);
    const details = [...feedback.querySelectorAll("details")];
    const safe = document.body.dataset.mode === "safe";
    counts.details += details.length;
    if (details.length !== (safe ? 0 : want.details)) {
      problems.push(`${where}: ${details.length} <details>, ${safe ? 0 : want.details} expected`);
    }
    checkText(where, visibleText(feedback), details.length ? " (details closed)" : "");
    for (const [i, d] of details.entries()) {
      const summary = d.firstElementChild;
      if (!summary || summary.tagName !== "SUMMARY" || !shown(summary) || !summary.innerText.trim()) {
        problems.push(`${where}: <details> ${i} has no visible <summary> first`);
      }
      const folded = [...d.children].filter((c) => c !== summary);
      if (d.open) problems.push(`${where}: <details> ${i} is open before a click`);
      if (folded.some(shown)) problems.push(`${where}: <details> ${i} shows its folded text while closed`);
      d.open = true;
      if (!folded.length || !folded.every(shown) || !folded.some((c) => c.innerText.trim())) {
        problems.push(`${where}: <details> ${i} shows no text once opened`);
      }
    }
    if (details.length) checkText(where, visibleText(feedback), " (details opened)");
    for (const d of details) d.open = false;
  }
  if (!counts.sections) problems.push("the page has no feedback");
  document.getElementById("verdict").textContent = JSON.stringify({problems, ...counts});
}
