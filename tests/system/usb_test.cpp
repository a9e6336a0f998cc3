// make usb's writer (qemu/tools/write_usb.sh) on a faked machine: disks in a sysfs tree of our own,
// a mounts table, device files that are plain files. It writes only a removable or USB whole disk,
// nothing of it mounted, at most 64 GiB unless forced, and only once confirmed.
#include "tests/system/system.h"

#include <filesystem>
#include <fstream>

namespace {

using namespace systest;
namespace fs = std::filesystem;

void put(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
}

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

struct FakeMachine {
    fs::path root;
    explicit FakeMachine(const std::string& test) : root(fs::absolute(build_dir() + "/test-tmp/usb/" + test)) {  // (absolute: the symlinks below)
        fs::remove_all(root);
        fs::create_directories(root / "dev");
        put(root / "proc/mounts", "/dev/nvme0n1p2 / ext4 rw 0 0\n");
        put(root / "proc/swaps", "Filename Type Size Used Priority\n");
        put(root / "modexlab.iso", std::string(5000, 'I'));
    }
    // a disk of `gib` GiB with `partitions` partitions; `usb`: its sysfs path runs through a USB bus
    void disk(const std::string& name, bool removable, double gib, int partitions, bool usb = false) {
        const fs::path real = root / (usb ? "sys/devices/pci0000:00/usb2/2-1/block/" : "sys/devices/pci0000:00/ata1/block/") / name;
        put(real / "removable", removable ? "1\n" : "0\n");
        put(real / "size", std::to_string(uint64_t(gib * 1024 * 1024 * 2)) + "\n");
        put(real / "device/vendor", "Acme    \n");
        put(real / "device/model", "Stick           \n");
        for (int i = 1; i <= partitions; ++i) {
            put(real / (name + std::to_string(i)) / "partition", std::to_string(i) + "\n");
            put(real / (name + std::to_string(i)) / "size", "2048\n");
            put(root / "dev" / (name + std::to_string(i)), "");
            fs::create_directories(root / "sys/class/block" / (name + std::to_string(i)));
            put(root / "sys/class/block" / (name + std::to_string(i)) / "partition", std::to_string(i) + "\n");
        }
        fs::create_directories(root / "sys/block");
        fs::create_symlink(real, root / "sys/block" / name);
        put(root / "dev" / name, std::string(8000, 'D'));
    }
    ToolRun write(const std::string& device, const std::string& env = "YES=1", const std::string& answer = "") {
        const std::string script = fs::absolute(build_dir() + "/../qemu/tools/write_usb.sh").string();
        return run_command("printf '" + answer + "\\n' | env MODEXLAB_SYSFS=" + (root / "sys").string() + " MODEXLAB_PROC=" +
                           (root / "proc").string() + " MODEXLAB_DEV=" + (root / "dev").string() + " DEVICE=" + device + " " + env +
                           " " + script + " " + (root / "modexlab.iso").string());
    }
    std::string device(const std::string& name) { return read(root / "dev" / name); }
};

bool written(FakeMachine& m, const std::string& name) { return m.device(name).substr(0, 5000) == std::string(5000, 'I'); }
bool untouched(FakeMachine& m, const std::string& name) { return m.device(name) == std::string(8000, 'D'); }

TEST(UsbWriter, WritesARemovableStickAndShowsWhatItOverwrites) {
    FakeMachine m("stick");
    m.disk("sdz", true, 7.5, 2);
    ToolRun r = m.write("/dev/sdz");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(written(m, "sdz")) << r.out;
    EXPECT_NE(r.out.find("about to overwrite /dev/sdz, whole"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Acme Stick, 8 GiB"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("partition /dev/sdz1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("partition /dev/sdz2"), std::string::npos) << r.out;
}

TEST(UsbWriter, AUsbDiskThatSaysItIsFixedIsTaken) {
    FakeMachine m("usb-fixed");
    m.disk("sdy", false, 32, 1, true);
    ToolRun r = m.write("/dev/sdy");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(written(m, "sdy"));
}

TEST(UsbWriter, RefusesFixedDisksPartitionsMountsSwapAndUnknownDevices) {
    FakeMachine m("refusals");
    m.disk("sda", false, 500, 2);
    m.disk("sdz", true, 16, 2);
    struct Case {
        std::string device, says;
    };
    for (const Case& c : {Case{"/dev/sda", "neither removable nor on USB"}, Case{"/dev/sdz1", "is a partition"},
                          Case{"/dev/sdq", "not a disk this machine has"}, Case{"sdz", "a device path"}, Case{"", "name the stick"}}) {
        ToolRun r = m.write(c.device);
        EXPECT_EQ(r.status, 1) << c.device << ": " << r.out;
        EXPECT_NE(r.out.find(c.says), std::string::npos) << c.device << ": " << r.out;
        EXPECT_NE(r.out.find("nothing was written"), std::string::npos) << r.out;
    }
    EXPECT_TRUE(untouched(m, "sda"));
    put(m.root / "proc/mounts", "/dev/nvme0n1p2 / ext4 rw 0 0\n/dev/sdz2 /media/stick vfat rw 0 0\n");
    ToolRun r = m.write("/dev/sdz");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("/dev/sdz2 is mounted at /media/stick"), std::string::npos) << r.out;
    put(m.root / "proc/mounts", "/dev/nvme0n1p2 / ext4 rw 0 0\n");
    put(m.root / "proc/swaps", "Filename Type Size Used Priority\n/dev/sdz1 partition 1024 0 -2\n");
    r = m.write("/dev/sdz");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("/dev/sdz1 is in use as swap"), std::string::npos) << r.out;
    EXPECT_TRUE(untouched(m, "sdz"));
}

TEST(UsbWriter, LargeDisksOnlyWhenForced) {
    FakeMachine m("large");
    m.disk("sdx", true, 128, 1);
    ToolRun r = m.write("/dev/sdx");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("holds 128 GiB, more than 64 GiB"), std::string::npos) << r.out;
    EXPECT_TRUE(untouched(m, "sdx"));
    r = m.write("/dev/sdx", "YES=1 FORCE=1");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(written(m, "sdx"));
}

TEST(UsbWriter, AsksForTheDevicesNameUnlessToldYes) {
    FakeMachine m("confirm");
    m.disk("sdw", true, 4, 1);
    ToolRun r = m.write("/dev/sdw", "", "yes");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("type sdw to go on"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("not confirmed"), std::string::npos) << r.out;
    EXPECT_TRUE(untouched(m, "sdw"));
    r = m.write("/dev/sdw", "", "sdw");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(written(m, "sdw"));
}

}  // namespace
