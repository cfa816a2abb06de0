"""The report's table of contents (corlab.html_table.with_contents): one entry per <h2>, each
linking to an id that exists, in order, with unique ids."""
# SPDX-License-Identifier: BSD-3-Clause
import re

from corlab.html_table import with_contents


def test_every_section_is_in_the_contents_and_its_link_resolves():
    body = ("<h1>t</h1><p>intro</p><h2>Summary</h2><p>a</p><h2>Fits (95 %, <i>t</i>)</h2>"
            "<h3>sub</h3><h2>Summary</h2>")
    out = with_contents(body)
    links = re.findall(r'<a href="#([^"]+)">', out)
    ids = re.findall(r'<h2 id="([^"]+)">', out)
    assert links == ids == ["summary", "fits-95-t", "summary-2"]
    assert out.index('<nav class="toc">') < out.index('<h2 id="summary">')
    assert out.index("<p>intro</p>") < out.index('<nav class="toc">')


def test_a_page_without_sections_is_unchanged():
    assert with_contents("<h1>t</h1><p>x</p>") == "<h1>t</h1><p>x</p>"
