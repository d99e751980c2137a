## The errors' and warnings' messages, in English (the default; the contract's tests read
## these). Each key is one message; its variables are named as the code names them. The
## other languages' files have the same keys and variables (tests/core/test_messages.py).

## the words of other programs: an operating system's reason, a file reader's complaint
reason = { $text }
problem = { $text }

## reading files (model/files.py)
model-not-a-path = a model is a file path, a dict or a Mechanism, not { $type }
file-empty = the file is empty
model-not-a-mapping = a model is a mapping with keys points, bodies, joints, drivers; this file holds { $holds }
holds = { $what ->
        [list] a list
        [text] a text
        [nothing] nothing
       *[value] a single value
    }
file-type-unknown = unknown file type { $suffix }: { $noun ->
        [cam] a cam file
       *[model] a model file
    } ends in { $suffixes }
file-not-utf8 = the file is not UTF-8 text (byte { $byte })
file-missing = no such file
file-unreadable = cannot read the file: { $reason }
file-is-a-folder = this is a folder, not a model file
file-too-large = the file is too large for a model (more than { $limit } bytes)
file-no-end = the file gave no end within { $seconds } s (a pipe or a device, not a model file)
text-too-large = the text is too large for a model (more than { $limit } characters)
text-unreadable = unreadable { $format }: { $detail }
file-too-deep = the file is nested too deeply to be a model (more than { $levels } levels{ $line ->
        [0] {""}
       *[other] , line { $line }
    })
name-too-long = the name { $name } has { $length } characters: names have at most { $limit }
text-lone-surrogate = the text { $text } holds a lone surrogate, which is not Unicode text
key-duplicate = duplicate key { $key }{ $line ->
        [0] {""}
       *[other] {" "}at line { $line }
    }: each key may appear only once
json-invalid = invalid JSON at line { $line }, column { $column }: { $problem }
toml-invalid = invalid TOML: { $problem }
yaml-invalid = invalid YAML{ $line ->
        [0] {""}
       *[other] {" "}at line { $line }, column { $column }
    }: { $problem }
yaml-alias-inside = the alias *{ $alias } at line { $line } is inside what it names
yaml-alias-unknown = the alias *{ $alias } at line { $line } names no anchor
yaml-aliases-too-many = the aliases expand to more than { $limit } values (at line { $line }): too many for a model
model-no-cam = this model has no cam: give a body a `cam:` shape
