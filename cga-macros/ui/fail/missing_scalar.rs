cga_macros::algebra! {
    signature = (3, 0);
    type Vector = [grade(1)];
}

fn main() {}
