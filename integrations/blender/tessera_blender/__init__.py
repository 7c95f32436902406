# tessera_blender — Blender add-on: File > Import > tessera (.json) imports a tessera
# arrangement or exemplar (docs/format.md) as instances of its element meshes, one
# collection per element class. The import itself is tessera_blender.importer
# (import_tessera_json), usable from scripts; tessera_blender.data reads the files and
# needs no Blender. See integrations/blender/README.md.
bl_info = {
    "name": "tessera",
    "author": "tessera contributors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > tessera (.json)",
    "description": "Import tessera element arrangements and animations (JSON) as instances of the element meshes",
    "doc_url": "",
    "category": "Import-Export",
}

try:
    import bpy
except ImportError:  # plain Python: only tessera_blender.data is usable
    bpy = None

if bpy is not None:
    if "importer" in locals():  # F8 / "Reload Scripts"
        import importlib

        importlib.reload(data)  # noqa: F821 (defined on the first load)
        importlib.reload(importer)  # noqa: F821
    else:
        from . import data, importer

    from bpy.props import EnumProperty, StringProperty
    from bpy_extras.io_utils import ImportHelper

    class ImportTesseraJson(bpy.types.Operator, ImportHelper):
        """Import a tessera arrangement, exemplar or animation (.json) as instances of the element meshes"""

        bl_idname = "import_scene.tessera_json"
        bl_label = "Import tessera JSON"
        bl_options = {"REGISTER", "UNDO", "PRESET"}

        filename_ext = ".json"
        filter_glob: StringProperty(default="*.json", options={"HIDDEN"})

        instancing: EnumProperty(
            name="Instancing",
            description="How elements of rigid types with a mesh share it",
            items=(
                ("collection", "Collection instances",
                 "An Empty per element instancing the class's prototype collection"),
                ("linked", "Linked meshes", "A mesh object per element sharing the class's mesh data"),
            ),
            default="collection",
        )
        tessera_executable: StringProperty(
            name="tessera executable",
            description="The tessera command-line tool, used to rebuild the meshes of deformable types "
                        "(empty: $TESSERA_CLI, else tessera on PATH); without it they are shown undeformed",
            default="",
            subtype="FILE_PATH",
        )

        def execute(self, context):
            try:
                result = importer.import_tessera_json(self.filepath, instancing=self.instancing,
                                                      tessera=self.tessera_executable or None, context=context)
            except (ValueError, OSError) as e:
                self.report({"ERROR"}, str(e))
                return {"CANCELLED"}
            for w in result.warnings:
                self.report({"WARNING"}, w)
            self.report({"INFO"}, f"tessera: {len(result.objects)} elements of {len(result.prototypes)} classes "
                                  f"in collection '{result.collection.name}'")
            return {"FINISHED"}

    def menu_func_import(self, context):
        self.layout.operator(ImportTesseraJson.bl_idname, text="tessera (.json)")

    def register():
        bpy.utils.register_class(ImportTesseraJson)
        bpy.types.TOPBAR_MT_file_import.append(menu_func_import)

    def unregister():
        bpy.types.TOPBAR_MT_file_import.remove(menu_func_import)
        bpy.utils.unregister_class(ImportTesseraJson)

else:

    def register():
        raise RuntimeError("tessera_blender.register() needs Blender (bpy)")

    def unregister():
        pass
