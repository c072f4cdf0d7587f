"""scripts/check-layers can fail: on a copy of the source tree it passes, and each kind of breach
injected into the copy (an upward include in a header, in a source file, in a layer's tests; a link
removed from CMakeLists.txt that an include needs; a declared link nothing uses; an include of no
layer) makes it fail with a message naming the file and line, or the link. ctest runs it (label
tooling; tests/CMakeLists.txt)."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE_TREE = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..'))
SCRIPT = os.path.join(SOURCE_TREE, 'scripts', 'check-layers')
COPIED = ['src', 'include', 'apps', os.path.join('python', 'src'), 'tests']


class CheckLayersTest(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix='check-layers-')
        self.addCleanup(shutil.rmtree, self.root)
        shutil.copy(os.path.join(SOURCE_TREE, 'CMakeLists.txt'), self.root)
        for folder in COPIED:
            shutil.copytree(os.path.join(SOURCE_TREE, folder), os.path.join(self.root, folder))

    def run_check(self):
        result = subprocess.run([sys.executable, SCRIPT, '--root', self.root], capture_output=True, text=True)
        return result.returncode, result.stdout + result.stderr

    def write(self, relative, text):
        path = os.path.join(self.root, relative)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w', encoding='utf-8') as f:
            f.write(text)

    def edit_cmake(self, old, new):
        path = os.path.join(self.root, 'CMakeLists.txt')
        with open(path, encoding='utf-8') as f:
            text = f.read()
        self.assertIn(old, text)
        with open(path, 'w', encoding='utf-8') as f:
            f.write(text.replace(old, new))

    def expect_failure(self, *fragments):
        code, output = self.run_check()
        self.assertEqual(code, 1, output)
        for fragment in fragments:
            self.assertIn(fragment, output)

    def test_the_unchanged_copy_passes(self):
        code, output = self.run_check()
        self.assertEqual(code, 0, output)

    def test_an_upward_include_in_a_header_fails(self):
        self.write('include/pmdplan/collision/upward_probe.hpp',
                   '// A header of collision that reaches up.\n#pragma once\n#include "pmdplan/planning/planning_space.hpp"\n')
        self.expect_failure('include/pmdplan/collision/upward_probe.hpp:3: layer collision includes pmdplan/planning/')

    def test_an_upward_include_in_a_source_file_fails(self):
        self.write('src/core/upward_probe.cpp', '#include "pmdplan/core/input_error.hpp"\n#include "pmdplan/io/files/path_file.hpp"\n')
        self.expect_failure('src/core/upward_probe.cpp:2: layer core includes pmdplan/io/')

    def test_a_sideways_include_between_unlinked_layers_fails(self):
        # glove and model are side by side: neither links the other.
        self.write('src/glove/sideways_probe.cpp', '#include "pmdplan/model/robot_model.hpp"\n')
        self.expect_failure('src/glove/sideways_probe.cpp:1: layer glove includes pmdplan/model/')

    def test_a_layers_tests_may_not_include_a_layer_above_it(self):
        self.write('tests/model/upward_probe_test.cpp', '#include "pmdplan/collision/collision_checking.hpp"\n')
        self.expect_failure('tests/model/upward_probe_test.cpp:1: layer model includes pmdplan/collision/')

    def test_removing_a_link_an_include_needs_fails(self):
        self.edit_cmake('pmdplan_trajectory pmdplan_planning nlohmann_json', 'pmdplan_trajectory nlohmann_json')
        self.expect_failure('layer io includes pmdplan/planning/', 'PMDPLAN_LAYER_DEPS_io')

    def test_a_declared_link_nothing_includes_fails(self):
        self.edit_cmake('set(PMDPLAN_LAYER_DEPS_model     pmdplan_core', 'set(PMDPLAN_LAYER_DEPS_model     pmdplan_glove pmdplan_core')
        self.expect_failure('PMDPLAN_LAYER_DEPS_model links pmdplan_glove, but no file of model includes pmdplan/glove/')

    def test_front_ends_include_any_layer_but_not_an_unknown_one(self):
        self.write('apps/pmdplan/probe_command.cpp', '#include "pmdplan/bench/campaign.hpp"\n#include "pmdplan/core/input_error.hpp"\n')
        code, output = self.run_check()
        self.assertEqual(code, 0, output)
        self.write('python/src/probe.cpp', '#include "pmdplan/nosuchlayer/thing.hpp"\n')
        self.expect_failure('python/src/probe.cpp:1: includes pmdplan/nosuchlayer/, which is no layer')


if __name__ == '__main__':
    unittest.main()
