"""The one binary buffer of the glTF files the make_*.py scripts here write: typed arrays
appended four-byte aligned, each with its buffer view and accessor, embedded as a data URI."""
import base64
import struct


class GltfBuffer:
    def __init__(self):
        self.blob = bytearray()
        self.views = []
        self.accessors = []

    def add(self, data, fmt, count, type_, component, target=None, minmax=None):
        """Appends `data` packed as `fmt`; returns its accessor's index."""
        while len(self.blob) % 4:
            self.blob.append(0)
        offset = len(self.blob)
        self.blob.extend(struct.pack("<" + fmt * len(data), *data))
        view = {"buffer": 0, "byteOffset": offset, "byteLength": len(self.blob) - offset}
        if target:
            view["target"] = target
        self.views.append(view)
        acc = {"bufferView": len(self.views) - 1, "componentType": component, "count": count, "type": type_}
        if minmax:
            acc["min"], acc["max"] = minmax
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def buffers(self):
        return [{"byteLength": len(self.blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()}]
