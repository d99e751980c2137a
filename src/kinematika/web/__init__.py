"""The interactive page (`kinematika app`): a small JSON API over the one engine, and the
static page that draws the mechanism from the API's data.

`server.create_app` builds the Starlette application; `requests` reads and checks the
JSON bodies; `scene_json` exports a drawing's `Scene` as data; `edit` turns a drag of a
point into an edit of the model's text; `static/` holds the page (plain HTML, CSS and
JavaScript modules, nothing fetched from elsewhere).
"""
